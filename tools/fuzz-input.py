#!/usr/bin/env python3
"""Bad-input fuzzing of `hvsph run` (not part of `make check`; docs/design.md, "Bad input").

Four modes, each N tries from a seed:
  cases      mutates the example case files (a line deleted, doubled or indented, a value
             replaced by a wrong one, a key renamed, the file cut short) and sets each up;
  sets       runs example cases with 1 to 3 random `--set KEY=VALUE` of keys that runs
             read (taken from the used_parameters.yaml files given) and wrong or odd
             values, for two outputs (so the steps run too);
  snapshots  damages one particle snapshot (.csv: a line deleted, doubled or swapped, a
             field replaced, the header changed, the file cut short; .vtu: an attribute of
             its XML changed, a tag removed, bytes of the header or the data overwritten,
             the file cut short) of a copy of RUNDIR, a run with `output.csv: true`, and
             renders it (radiograph or particles), renders the folder, or measures it;
  tables     damages a tabulated EOS (the docs/models.md example: a token replaced or
             added, a line deleted, doubled or joined, the file cut short) and runs a small
             block of it for two outputs.
A try passes when hvsph exits 0, or 2 (bad input; 3 in `sets` and `tables`, a failed run)
with exactly one "hvsph: error:" line, which in `cases` names the case file and in
`snapshots` the snapshot rendered alone. Anything else (a crash, a signal, a hang past 60 s,
several errors, a message without the file) is printed as BAD with the input kept in the
work folder. On a build with the sanitizers (`-DHVSPH_SANITIZE=ON`), run with
UBSAN_OPTIONS=halt_on_error=1 so that undefined behaviour fails the try.

usage: tools/fuzz-input.py BIN cases SEED N [WORKDIR]
       tools/fuzz-input.py BIN sets SEED N WORKDIR USED_PARAMETERS.yaml...
       tools/fuzz-input.py BIN snapshots SEED N WORKDIR RUNDIR
       tools/fuzz-input.py BIN tables SEED N WORKDIR
"""
import glob
import os
import random
import re
import shutil
import subprocess
import sys

VALUES = ['0', '-1', '1e308', '-1e308', 'nan', 'inf', '.nan', 'abc', '[]', '{}', '[1, 2]',
          '"1 km"', '"5 furlong"', '1e-300', '"-3 mm"', '~', '""', '"1.5 mm/us"', 'yes',
          '2147483648', '-0', '0x10', '"1e400 m"', '0.5', '1e9', '"3 GPa"', '"2 us"']
KEYS = ['radius', 'spacing', 'material', 'min', 'max', 'shape', 'type', 'center', 'axis',
        'length', 'velocity', 'speed', 'end', 'every']
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd):
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=60, errors='replace')
        return r.returncode, r.stderr
    except subprocess.TimeoutExpired:
        return 'timeout', ''


def errors(err):
    return sum(1 for line in err.splitlines() if line.startswith('hvsph: error:'))


def mutate(lines):
    op = random.choice(['del', 'dup', 'val', 'val', 'val', 'trunc', 'indent', 'key'])
    i = random.randrange(len(lines))
    out = list(lines)
    if op == 'del':
        del out[i]
    elif op == 'dup':
        out.insert(i, out[i])
    elif op == 'val':
        spans = list(re.finditer(r'(?<=[:\[,] )[^,\]\}\n#]+', out[i]))
        if spans:
            m = random.choice(spans)
            out[i] = out[i][:m.start()] + random.choice(VALUES) + out[i][m.end():]
    elif op == 'trunc':
        text = ''.join(out)
        return [text[:random.randrange(len(text))]]
    elif op == 'indent':
        out[i] = ' ' + out[i]
    else:
        out[i] = re.sub(r'^(\s*-?\s*)(\w+):',
                        lambda m: m.group(1) + random.choice(KEYS) + ':', out[i], count=1)
    return out


def fuzz_cases(binary, n, work):
    cases = sorted(glob.glob(os.path.join(ROOT, 'examples', '**', '*.yaml'), recursive=True))
    bad = 0
    for it in range(n):
        src = random.choice(cases)
        lines = mutate(open(src).read().splitlines(True))
        if random.random() < 0.3:
            lines = mutate(lines)
        path = os.path.join(work, 'case.yaml')
        open(path, 'w').write(''.join(lines))
        rc, err = run([binary, 'run', path, '-o', os.path.join(work, 'out'), '--overwrite',
                       '--set', 'time.end=0', '--threads', '1', '--quiet'])
        if not (rc == 0 or (rc == 2 and errors(err) == 1 and 'case.yaml' in err)):
            bad += 1
            keep = os.path.join(work, 'bad_%d.yaml' % it)
            open(keep, 'w').write(''.join(lines))
            print('BAD', it, os.path.basename(src), rc, err.strip()[-400:], '->', keep, flush=True)
    return bad


def fuzz_sets(binary, n, work, used):
    keys = set()
    for up in used:
        path = []
        for line in open(up):
            if not line.strip() or line.lstrip().startswith('#'):
                continue
            m = re.match(r'(\s*)(-\s*)?([A-Za-z_0-9]+):\s*(.*)', line)
            if not m:
                continue
            path = path[:len(m.group(1)) // 2] + [m.group(3)]
            if m.group(4) and not m.group(4).startswith('#'):
                keys.add('.'.join(path))
    keys = sorted(k for k in keys if not k.startswith('bodies'))
    cases = [os.path.join(ROOT, 'examples', c) for c in
             ('paper/bumper-1.yaml', 'paper/vessel.yaml', 'verification/sod.yaml',
              'verification/taylor_bar.yaml')]
    bad = 0
    for it in range(n):
        sets = []
        for _ in range(random.randint(1, 3)):
            sets += ['--set', '%s=%s' % (random.choice(keys), random.choice(VALUES))]
        case = random.choice(cases)
        rc, err = run([binary, 'run', case, '-o', os.path.join(work, 'out'), '--overwrite',
                       '--threads', '1', '--quiet', '--set', 'resolution=0.02'] + sets +
                      ['--set', 'time.end=2e-7', '--set', 'output.every=1e-7'])
        if not (rc == 0 or (rc in (2, 3) and errors(err) == 1)):
            bad += 1
            print('BAD', it, os.path.basename(case), ' '.join(sets), rc, err.strip()[-300:],
                  flush=True)
    print('keys', len(keys))
    return bad


ODD = ['nan', 'inf', '-inf', '1e308', '-1', 'abc', '', '2147483648', '-2147483649', '99999',
       '1e-320', '0', '-0', '9223372036854775807', '1e400', ' ', '0x10', '"', '1e8', '2']


def edit_lines(lines, op, i):
    """The whole-line damages both text formats share: 'del', 'dup', 'swap' (line i with
    another), 'join' (line i with the next), 'trunc' (the text cut anywhere). Returns the
    new lines, or None for another op."""
    if op == 'del':
        return lines[:i] + lines[i + 1:]
    if op == 'dup':
        return lines[:i + 1] + lines[i:]
    if op == 'swap':
        j = random.randrange(len(lines))
        lines = list(lines)
        lines[i], lines[j] = lines[j], lines[i]
        return lines
    if op == 'join':
        return lines[:i] + [' '.join(lines[i:i + 2])] + lines[i + 2:]
    if op == 'trunc':
        text = '\n'.join(lines)
        return text[:random.randrange(len(text) + 1)].split('\n')
    return None


def damage_csv(text):
    lines = text.split('\n')
    op = random.choice(['del', 'dup', 'field', 'field', 'field', 'trunc', 'header', 'swap'])
    i = random.randrange(len(lines))
    edited = edit_lines(lines, op, i)
    if edited is not None:
        return '\n'.join(edited)
    if op in ('field', 'header'):
        if op == 'header':
            i = random.randrange(min(3, len(lines)))
        f = lines[i].split(',')
        k = random.randrange(len(f))
        f[k] = random.choice(ODD + ['id', 'x', 'mat', 'body'])
        if random.random() < 0.2:
            del f[k]
        lines[i] = ','.join(f)
    return '\n'.join(lines)


def damage_vtu(data):
    head = data.find(b'<AppendedData')
    head = head if head > 0 else len(data)
    op = random.choice(['trunc', 'attr', 'attr', 'attr', 'bytes', 'tag', 'head'])
    if op == 'trunc':
        return data[:random.randrange(len(data))]
    if op == 'attr':
        m = random.choice(list(re.finditer(rb'="([^"]*)"', data[:head])))
        v = random.choice([x.encode() for x in ODD] +
                          [b'Float32', b'Int64', b'UInt8', b'ascii', b'binary', b'-5'])
        return data[:m.start(1)] + v + data[m.end(1):]
    if op == 'tag':
        m = random.choice(list(re.finditer(rb'<[^>]*>', data[:head])))
        return data[:m.start()] + data[m.end():]
    out = bytearray(data)
    lo, hi = (0, head) if op == 'head' else (head, len(out))
    for _ in range(random.randint(1, 4 if op == 'head' else 50)):
        out[random.randrange(lo, hi)] = random.randrange(256)
    return bytes(out)


def fuzz_snapshots(binary, n, work, rundir):
    snaps = sorted(glob.glob(os.path.join(rundir, 'particles_*.csv')))
    if not snaps:
        sys.exit('%s has no particles_*.csv: run a case with --set output.csv=true' % rundir)
    bad = 0
    for it in range(n):
        d = os.path.join(work, 'run')
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(rundir, d, ignore=shutil.ignore_patterns('checkpoint.hvc', 'frames'))
        ext = random.choice(['csv', 'vtu'])
        name = os.path.basename(random.choice(snaps))[:-3] + ext
        path = os.path.join(d, name)
        with open(path, 'rb') as f:   # read before the write truncates it
            data = f.read()
        if ext == 'csv':
            data = damage_csv(data.decode()).encode()
        else:
            data = damage_vtu(data)
        with open(path, 'wb') as f:
            f.write(data)
        if ext == 'vtu':
            for c in glob.glob(os.path.join(d, 'particles_*.csv')):   # measure reads .vtu
                os.remove(c)                                           # only without .csv
        mode = random.choice(['radiograph', 'particles', 'folder', 'measure'])
        if mode == 'measure':
            cmd = [binary, 'measure', d, '--quiet']
        elif mode == 'folder':
            cmd = [binary, 'render', d, '-o', os.path.join(d, 'frames'), '--size', '200',
                   '--quiet']
        else:
            cmd = [binary, 'render', path, '-o', os.path.join(d, 'pic.png'), '--size', '200',
                   '--mode', mode, '--color',
                   random.choice(['material', 'damage', 'velocity', 'pressure', 'density'])]
        rc, err = run(cmd)
        alone = mode in ('radiograph', 'particles')
        if not (rc == 0 or (rc == 2 and errors(err) == 1 and (not alone or name in err))):
            bad += 1
            keep = os.path.join(work, 'bad_%d' % it)
            shutil.rmtree(keep, ignore_errors=True)
            os.rename(d, keep)
            print('BAD', it, mode, name, rc, err.strip()[-400:], '->', keep, flush=True)
    return bad


TABLE = """# the docs/models.md example
rho_count 3 e_count 4
2000 2700 3500
0 1e5 1e6 1e7
-1e9  -9e8  0     9e9
 0     2e8  2e9   2e10
 2e10  2e10 2.3e10 4e10
5000 5010 5100 6000
5300 5310 5400 6300
5600 5610 5700 6600
"""
TABLE_CASE = """name: table
materials:
  tab: {eos: table, file: eos.txt, rho0: 2700}
domain: {min: [0, 0, 0], max: [0.02, 0.02, 0.02], boundary: {x: wall, y: periodic, z: periodic}}
bodies:
  - {name: block, material: tab, shape: {type: box, min: [0, 0, 0], max: [0.02, 0.02, 0.02]},
     spacing: 2 mm, energy: 2e5, velocity: [100, 0, 0]}
time: {end: 0.2 us}
output: {every: 0.1 us}
"""


def fuzz_tables(binary, n, work):
    open(os.path.join(work, 'case.yaml'), 'w').write(TABLE_CASE)
    bad = 0
    for it in range(n):
        lines = TABLE.split('\n')
        for _ in range(random.randint(1, 3)):
            op = random.choice(['del', 'dup', 'tok', 'tok', 'tok', 'trunc', 'join', 'add'])
            i = random.randrange(len(lines))
            edited = edit_lines(lines, op, i)
            if edited is not None:
                lines = edited
            else:
                toks = lines[i].split()
                if toks:
                    k = random.randrange(len(toks))
                    if op == 'tok':
                        toks[k] = random.choice(ODD + ['3', '1.5', '#', '1,2'])
                    else:
                        toks.insert(k, random.choice(ODD))
                lines[i] = ' '.join(toks)
        table = '\n'.join(lines)
        open(os.path.join(work, 'eos.txt'), 'w').write(table)
        rc, err = run([binary, 'run', os.path.join(work, 'case.yaml'), '-o',
                       os.path.join(work, 'out'), '--overwrite', '--threads', '1', '--quiet'])
        if not (rc == 0 or (rc in (2, 3) and errors(err) == 1)):
            bad += 1
            keep = os.path.join(work, 'bad_%d.txt' % it)
            open(keep, 'w').write(table)
            print('BAD', it, rc, err.strip()[-400:], '->', keep, flush=True)
    return bad


def main():
    modes = ('cases', 'sets', 'snapshots', 'tables')
    if len(sys.argv) < 5 or sys.argv[2] not in modes or \
            (sys.argv[2] == 'snapshots' and len(sys.argv) != 7):
        sys.exit(__doc__)
    binary, mode, seed, n = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    work = sys.argv[5] if len(sys.argv) > 5 else '/tmp/hvsph-fuzz'
    os.makedirs(work, exist_ok=True)
    random.seed(seed)
    if mode == 'cases':
        bad = fuzz_cases(binary, n, work)
    elif mode == 'sets':
        bad = fuzz_sets(binary, n, work, sys.argv[6:])
    elif mode == 'snapshots':
        bad = fuzz_snapshots(binary, n, work, sys.argv[6])
    else:
        bad = fuzz_tables(binary, n, work)
    print('done', n, 'tries,', bad, 'bad')
    sys.exit(1 if bad else 0)


if __name__ == '__main__':
    main()
