import numpy as np, re
def read(path):
    raw = open(path, "rb").read()
    i = raw.index(b"<AppendedData encoding=\"raw\">"); j = raw.index(b"_", i) + 1
    head = raw[:i].decode()
    t = float(re.search(r'Name="TIME"[^>]*>([^<]+)<', head).group(1))
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"', head):
        ty, name, nc, off = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        n = int(np.frombuffer(raw, np.uint64, 1, j + off)[0])
        dt = {"Int64": np.int64, "Int32": np.int32, "Float64": np.float64, "UInt8": np.uint8}[ty]
        a = np.frombuffer(raw, dt, n // np.dtype(dt).itemsize, j + off + 8)
        out[name] = a.reshape(-1, nc) if nc > 1 else a
    d = {"t": t, "m": out["m"], "rho": out["rho"], "p": out["p"], "body": out["body"], "id": out["id"], "e": out["e"],
         "damage": out["damage"]}
    d["x"], d["y"], d["z"] = out["x"][:, 0], out["x"][:, 1], out["x"][:, 2]
    d["vx"], d["vy"], d["vz"] = out["v"][:, 0], out["v"][:, 1], out["v"][:, 2]
    return d
def read_csv(path):
    t = float(open(path).readline().split()[6])
    a = np.genfromtxt(path, delimiter=",", skip_header=2, names=True)
    d = {k: a[k] for k in a.dtype.names}; d["t"] = t
    return d
def load(path):
    return read(path) if path.endswith(".vtu") else read_csv(path)
