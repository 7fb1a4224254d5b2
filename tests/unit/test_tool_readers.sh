#!/usr/bin/env bash
# test_tool_readers.sh — the files hvsph writes are read by the tools its users have:
#  1. meshio (python3-meshio) and vtk (python3-vtk9, vtkXMLUnstructuredGridReader) read
#     every snapshot, plain and compressed (output.compress), with the point count of
#     the CSV snapshot of the same output, every array as long as the points and equal,
#     value for value, to the CSV's columns (the CSV's %.17g reads back exactly); TIME
#     and STEP as the CSV's comment line says; the material and body names as FieldData
#     ("mat <name>", "body <name>" = index). meshio 7.0 read `body` as twice the points
#     before the blocks were reversed (vtu.c). Cases: examples/verification/tiny.yaml
#     (gas, 3,024 particles, two bodies) and examples/paper/bumper-1.yaml at resolution
#     0.04 (solid: S with 6 components, eps_p, damage; a half model), a few steps;
#  2. the compressed snapshots are smaller, hold the same arrays as the plain ones, and
#     hvsph's own reader takes them: `hvsph render` of a compressed snapshot makes the
#     same picture, byte for byte, as of the plain one;
#  3. docs/output-files.md's mirroring of a half model: vtkReflectionFilter, plane Z,
#     centre 0, FlipAllInputArrays, doubles the points and negates z, v_z, S_yz, S_xz;
#  5. an axisymmetric snapshot's FieldData GEOMETRY, in the very line vtu.c writes
#     (test_io checks the writer's bytes): meshio and vtk read a snapshot holding it, with
#     GEOMETRY = 1 among the field data and the points and arrays as before; and
#     docs/output-files.md's Reflect (plane Y, centre 0, flip all arrays) gives both halves
#     of the meridional plane, negating y, v_y, S_xy, S_yz;
#  4. docs/output-files.md's numpy recipe for summary.csv (the ```python block of the
#     page that reads "summary.csv"), run as written in a run's folder, gives the
#     file's columns by name and its rows.
# A part whose Python module is missing is skipped with a note; when none can run the
# test exits 77, which ctest reports as skipped (tools/install-deps.sh installs them).
set -u
BIN=${HVSPH_BIN:-build/hvsph}
SRC=${HVSPH_SOURCE_DIR:-.}
T=${HVSPH_TMP:-/tmp/hvsph_test_tool_readers}
rm -rf "$T" && mkdir -p "$T"
pass=0 fail=0 ran=0
check() {  # check CONDITION-STATUS MESSAGE
  if [ "$1" -eq 0 ]; then pass=$((pass + 1)); echo "PASS: $2"; else fail=$((fail + 1)); echo "FAIL: $2"; fi
}
# the first python3 that has module $1 (the one on PATH may be another installation
# than Debian's, which has the python3-* packages)
python_with() {
  for py in python3 /usr/bin/python3; do
    if command -v "$py" >/dev/null 2>&1 && "$py" -c "import $1" >/dev/null 2>&1; then
      echo "$py"; return 0
    fi
  done
  return 1
}
NUMPY_PY=$(python_with numpy) || NUMPY_PY=
MESHIO_PY=$(python_with meshio) || MESHIO_PY=
VTK_PY=$(python_with vtk) || VTK_PY=
if [ -z "$NUMPY_PY" ]; then
  echo "SKIP: no python3 with numpy (python3-numpy; tools/install-deps.sh installs it)"
  exit 77
fi

# the runs: each writes CSV and VTU snapshots of the same outputs
TINY=$SRC/examples/verification/tiny.yaml
BUMP=$SRC/examples/paper/bumper-1.yaml
BSETS=(--set resolution=0.04 --set time.end=0.3us --set output.every=0.15us --set output.csv=true)
"$BIN" run "$TINY" -o "$T/tiny" --quiet 2> "$T/tiny.log" &&
"$BIN" run "$TINY" -o "$T/tinyz" --set output.compress=true --quiet 2> "$T/tinyz.log" &&
"$BIN" run "$BUMP" -o "$T/bump" "${BSETS[@]}" --quiet 2> "$T/bump.log" &&
"$BIN" run "$BUMP" -o "$T/bumpz" "${BSETS[@]}" --set output.compress=true --quiet 2> "$T/bumpz.log"
check $? "four runs (tiny and bumper-1, plain and compressed) with CSV and VTU snapshots"

# 2. compressed: smaller, read by hvsph (render: the same picture)
small=0
for k in 00000 00004; do
  a=$(stat -c %s "$T/tiny/particles_$k.vtu") b=$(stat -c %s "$T/tinyz/particles_$k.vtu")
  echo "  tiny particles_$k.vtu: $a bytes, compressed $b"
  [ "$b" -lt "$a" ] || small=1
done
check $small "the compressed snapshots are smaller"
grep -q 'compressor="vtkZLibDataCompressor"' "$T/tinyz/particles_00004.vtu" &&
  ! grep -q 'compressor=' "$T/tiny/particles_00004.vtu"
check $? "only output.compress writes compressor=\"vtkZLibDataCompressor\""
# (each rendered from one path: the picture's Description names the snapshot)
mkdir -p "$T/r" && cp "$T/bump/particles_00002.vtu" "$T/r/" &&
  "$BIN" render "$T/r/particles_00002.vtu" -o "$T/plain.png" > "$T/render.log" 2>&1 &&
  cp "$T/bumpz/particles_00002.vtu" "$T/r/" &&
  "$BIN" render "$T/r/particles_00002.vtu" -o "$T/z.png" >> "$T/render.log" 2>&1 &&
  cmp -s "$T/plain.png" "$T/z.png"
check $? "hvsph render reads a compressed snapshot: the same picture as of the plain one"

# 1. and 3.: one Python program per reader, over every snapshot of the four runs
cat > "$T/readers.py" <<'PY'
import glob, os, sys
import numpy as np

reader, top = sys.argv[1], sys.argv[2]
bodies = {"tiny": ["left", "right"], "bump": ["projectile", "bumper", "bumper-core"]}
fails = []

def fail(msg):
    fails.append(msg)
    print("  " + msg)

def read_csv(path):
    with open(path) as f:
        lines = f.readlines()
    comments = [l for l in lines if l.startswith("#")]
    t = np.genfromtxt([l for l in lines if not l.startswith("#")], delimiter=",", names=True)
    return comments, np.atleast_1d(t)

def read_vtu(path):
    """points, {name: array (n, ncomp)}, {field-data name: value}"""
    if reader == "meshio":
        import meshio
        m = meshio.read(path)
        pd = {k: np.asarray(v).reshape(len(m.points), -1) if len(m.points) else np.asarray(v)
              for k, v in m.point_data.items()}
        fd = {k: np.asarray(v).ravel()[0] for k, v in m.field_data.items()}
        return np.asarray(m.points), pd, fd
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData())
    pdata = g.GetPointData()
    pd = {}
    for i in range(pdata.GetNumberOfArrays()):
        a = pdata.GetArray(i)
        pd[pdata.GetArrayName(i)] = vtk_to_numpy(a).reshape(a.GetNumberOfTuples(), -1)
    fdata = g.GetFieldData()
    fd = {fdata.GetArrayName(i): fdata.GetArray(i).GetTuple1(0)
          for i in range(fdata.GetNumberOfArrays())}
    return pts, pd, fd

SUFFIX = {3: ["_x", "_y", "_z"], 6: ["_xx", "_yy", "_zz", "_xy", "_yz", "_xz"], 1: [""]}
nsnap = narrays = 0
for run in ("tiny", "tinyz", "bump", "bumpz"):
    for vtu in sorted(glob.glob(os.path.join(top, run, "particles_*.vtu"))):
        name = os.path.relpath(vtu, top)
        comments, csv = read_csv(vtu[:-4] + ".csv")
        try:
            pts, pd, fd = read_vtu(vtu)
        except Exception as e:   # meshio 7.0 raised ValueError here before the fix
            fail(f"{name}: {reader} cannot read it: {e}")
            continue
        nsnap += 1
        n = len(csv)
        if pts.shape != (n, 3):
            fail(f"{name}: points {pts.shape}, the CSV has {n} particles")
            continue
        for d, c in enumerate("xyz"):
            if not np.array_equal(pts[:, d], csv[c]):
                fail(f"{name}: point {c} differs from the CSV")
        cols = set(csv.dtype.names) - {"x", "y", "z"}
        for arr, vals in pd.items():
            narrays += 1
            if vals.shape[0] != n:
                fail(f"{name}: array '{arr}' has {vals.shape[0]} tuples for {n} points")
                continue
            sfx = SUFFIX.get(vals.shape[1])
            if arr == "v":   # the CSV's velocity columns are vx, vy, vz
                sfx = ["x", "y", "z"]
            want = [arr + s for s in sfx] if sfx else []
            if not want or any(w not in cols for w in want):
                fail(f"{name}: array '{arr}' ({vals.shape[1]} components) not in the CSV")
                continue
            for c, w in enumerate(want):
                cols.discard(w)
                if not np.array_equal(vals[:, c].astype(np.float64), csv[w]):
                    fail(f"{name}: array '{arr}' component {c} differs from the CSV's {w}")
        if cols:
            fail(f"{name}: CSV columns without an array: {sorted(cols)}")
        head = comments[0].split()
        t, step = float(head[head.index("time") + 1]), int(head[head.index("step") + 1])
        if fd.get("TIME") != t or fd.get("STEP") != step:
            fail(f"{name}: TIME {fd.get('TIME')} STEP {fd.get('STEP')}, the CSV says {t} {step}")
        mats = {}
        for c in comments:
            if c.startswith("# materials"):
                mats = {m.split("=", 1)[1]: int(m.split("=", 1)[0]) for m in c.split()[2:]}
        want_fd = {f"mat {m}": k for m, k in mats.items()}
        want_fd.update({f"body {b}": k for k, b in enumerate(bodies[run.rstrip("z")])})
        got_fd = {k: v for k, v in fd.items() if k.startswith(("mat ", "body "))}
        if not mats or got_fd != want_fd:
            fail(f"{name}: FieldData names {got_fd}, want {want_fd}")
        # the values are the indices the points carry
        if set(np.unique(pd["body"])) - set(want_fd[k] for k in want_fd if k.startswith("body ")):
            fail(f"{name}: a body index without a name")

# the compressed runs hold the same arrays as the plain ones
for run in ("tiny", "bump"):
    for vtu in sorted(glob.glob(os.path.join(top, run, "particles_*.vtu"))):
        zvtu = vtu.replace(os.sep + run + os.sep, os.sep + run + "z" + os.sep)
        a, b = read_vtu(vtu), read_vtu(zvtu)
        if not (np.array_equal(a[0], b[0]) and a[1].keys() == b[1].keys()
                and all(np.array_equal(a[1][k], b[1][k]) for k in a[1])):
            fail(f"{os.path.relpath(zvtu, top)}: not the arrays of the plain snapshot")

# mirroring a half model as docs/output-files.md says (vtk only)
if reader == "vtk":
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    for run in ("bump", "bumpz"):
        path = os.path.join(top, run, "particles_00002.vtu")
        r = vtk.vtkXMLUnstructuredGridReader()
        r.SetFileName(path)
        f = vtk.vtkReflectionFilter()
        f.SetInputConnection(r.GetOutputPort())
        f.SetPlaneToZ()
        f.SetCenter(0.0)
        f.CopyInputOn()
        f.FlipAllInputArraysOn()
        f.Update()
        g, o = r.GetOutput(), f.GetOutput()
        n = g.GetNumberOfPoints()
        x0, x1 = vtk_to_numpy(g.GetPoints().GetData()), vtk_to_numpy(o.GetPoints().GetData())
        get = lambda ds, a: vtk_to_numpy(ds.GetPointData().GetArray(a))
        v0, v1, s0, s1 = get(g, "v"), get(o, "v"), get(g, "S"), get(o, "S")
        flip3, flip6 = np.array([1, 1, -1]), np.array([1, 1, 1, 1, -1, -1])
        # the filter's points are Float32 (the arrays keep their type): to 1e-6
        ok = (o.GetNumberOfPoints() == 2 * n
              and np.allclose(x1[n:], x0 * flip3, rtol=1e-6, atol=0)
              and np.array_equal(v1[n:], v0 * flip3) and np.array_equal(s1[n:], s0 * flip6)
              and np.array_equal(get(o, "p")[n:], get(g, "p")) and (x0[:, 2] > 0).all())
        if not ok:
            fail(f"{run}: the Reflect filter (Z, centre 0, flip all arrays) does not mirror "
                 f"the half model as docs/output-files.md says")
        else:
            print(f"  {run}: Reflect Z at 0: {n} -> {2 * n} points, z, v_z, S_yz, S_xz negated")

print(f"  {reader}: {nsnap} snapshots, {narrays} arrays read, {len(fails)} problems")
sys.exit(1 if fails or nsnap < 12 else 0)
PY
for r in meshio vtk; do
  py=$MESHIO_PY
  [ "$r" = vtk ] && py=$VTK_PY
  if [ -z "$py" ]; then
    echo "NOTE: no python3 with $r (python3-$([ "$r" = vtk ] && echo vtk9 || echo meshio)); its part is skipped"
    continue
  fi
  if ! "$py" -c "import numpy" >/dev/null 2>&1; then
    echo "NOTE: $py has $r but not numpy; its part is skipped"
    continue
  fi
  ran=$((ran + 1))
  "$py" "$T/readers.py" "$r" "$T"
  check $? "$r reads every snapshot (plain and compressed): points, every array and value as the CSV, TIME, STEP, names"
done

# 4. the numpy recipe of docs/output-files.md, as written
DOC=$SRC/docs/output-files.md
awk '/^```python/ {inb = 1; blk = ""; next} /^```/ && inb {inb = 0; if (blk ~ /summary\.csv/ && !done) {printf "%s", blk; done = 1}; next}
     inb {blk = blk $0 "\n"}' "$DOC" > "$T/recipe.py"
grep -q genfromtxt "$T/recipe.py"
check $? "docs/output-files.md has a python recipe for summary.csv ($(wc -l < "$T/recipe.py") lines)"
cat "$T/recipe.py" - > "$T/recipe_check.py" <<'PY'
# appended by the test: the recipe's s holds every column of summary.csv by name
with open("summary.csv") as f:
    rows = [l for l in f if not l.startswith("#")]
names = rows[0].strip().split(",")
assert s.dtype.names == tuple(names), (s.dtype.names, names)
assert len(s) == len(rows) - 1 == 5, len(s)
assert s["step"][0] == 0 and s["time"][-1] == 0.02 and s["n"][0] == 3024
print("  recipe: %d columns, %d rows, e_total %.6g J at the end" % (len(names), len(s), s["e_total"][-1]))
PY
(cd "$T/tiny" && "$NUMPY_PY" "$T/recipe_check.py" > "$T/recipe.out" 2>&1)
rc=$?
cat "$T/recipe.out"
check $rc "the recipe, run in a run's folder, reads summary.csv's columns by name and its 5 rows"
# and genfromtxt(names=True) on the file itself takes the comment for the names (why the
# recipe drops the comment lines): if numpy ever skips it, the page can say so
(cd "$T/tiny" && "$NUMPY_PY" - <<'PY'
import sys
import numpy as np
try:
    s = np.genfromtxt("summary.csv", delimiter=",", names=True)
except ValueError as e:   # numpy 1.24: "Line #2 (got 18 columns instead of 1)"
    print("  genfromtxt alone: " + str(e).splitlines()[1].strip())
    sys.exit(0)
sys.exit(0 if "time" not in (s.dtype.names or ()) else 1)
PY
)
check $? "numpy's genfromtxt(names=True) alone takes the comment line for the names (as the page says)"

# 5. GEOMETRY: the line inserted after STEP (before the names, as vtu.c writes it); the
#    appended data's offsets count from its '_', so the header may grow
cat > "$T/rz.py" <<'PY'
import sys
import numpy as np
src, dst, reader = sys.argv[1], sys.argv[2], sys.argv[3]
b = open(src, "rb").read()
step = b.index(b'Name="STEP"')
eol = b.index(b"\n", step) + 1
line = b'      <DataArray type="Int32" Name="GEOMETRY" NumberOfTuples="1" format="ascii">1</DataArray>\n'
open(dst, "wb").write(b[:eol] + line + b[eol:])
if reader == "meshio":
    import meshio
    m, m0 = meshio.read(dst), meshio.read(src)
    g = np.asarray(m.field_data["GEOMETRY"]).ravel()[0]
    ok = g == 1 and np.array_equal(m.points, m0.points) and all(
        np.array_equal(m.point_data[k], m0.point_data[k]) for k in m0.point_data)
    print(f"  meshio: GEOMETRY {g}, {len(m.points)} points")
    sys.exit(0 if ok else 1)
import vtk
from vtk.util.numpy_support import vtk_to_numpy
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(dst)
f = vtk.vtkReflectionFilter()
f.SetInputConnection(r.GetOutputPort())
f.SetPlaneToY()
f.SetCenter(0.0)
f.CopyInputOn()
f.FlipAllInputArraysOn()
f.Update()
g, o = r.GetOutput(), f.GetOutput()
n = g.GetNumberOfPoints()
geo = g.GetFieldData().GetArray("GEOMETRY").GetTuple1(0)
x0, x1 = vtk_to_numpy(g.GetPoints().GetData()), vtk_to_numpy(o.GetPoints().GetData())
get = lambda ds, a: vtk_to_numpy(ds.GetPointData().GetArray(a))
flip3, flip6 = np.array([1, -1, 1]), np.array([1, 1, 1, -1, -1, 1])
ok = (geo == 1 and o.GetNumberOfPoints() == 2 * n
      and np.allclose(x1[n:], x0 * flip3, rtol=1e-6, atol=0)
      and np.array_equal(get(o, "v")[n:], get(g, "v") * flip3)
      and np.array_equal(get(o, "S")[n:], get(g, "S") * flip6))
print(f"  vtk: GEOMETRY {geo}; Reflect Y at 0: {n} -> {o.GetNumberOfPoints()} points")
sys.exit(0 if ok else 1)
PY
for r in meshio vtk; do
  py=$MESHIO_PY
  [ "$r" = vtk ] && py=$VTK_PY
  [ -n "$py" ] || continue
  "$py" "$T/rz.py" "$T/bump/particles_00002.vtu" "$T/rz_$r.vtu" "$r"
  check $? "$r reads a snapshot with FieldData GEOMETRY (an axisymmetric run's)"
done

echo "$pass passed, $fail failed"
[ $fail -eq 0 ] || exit 1
if [ $ran -eq 0 ]; then
  echo "SKIP: neither meshio nor vtk is installed (python3-meshio, python3-vtk9; tools/install-deps.sh installs them)"
  exit 77
fi
exit 0
