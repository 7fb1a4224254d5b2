#!/usr/bin/env python3
"""Bad-input fuzzing of `hvsph run` (not part of `make check`; docs/design.md, "Bad input").

Two modes, each N tries from a seed:
  cases  mutates the example case files (a line deleted, doubled or indented, a value
         replaced by a wrong one, a key renamed, the file cut short) and sets each up;
  sets   runs example cases with 1 to 3 random `--set KEY=VALUE` of keys that runs read
         (taken from the used_parameters.yaml files given) and wrong or odd values, for
         two outputs (so the steps run too).
A try passes when hvsph exits 0, or 2 (bad input; 3 in `sets`, a failed run) with exactly
one "hvsph: error:" line, which in `cases` names the case file. Anything else (a crash, a
signal, a hang past 60 s, several errors, a message without the file) is printed as BAD
with the input kept in the work folder.

usage: tools/fuzz-input.py BIN cases SEED N [WORKDIR]
       tools/fuzz-input.py BIN sets SEED N WORKDIR USED_PARAMETERS.yaml...
"""
import glob
import os
import random
import re
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
        rc, err = run([binary, 'run', path, '-o', os.path.join(work, 'out'), '--set',
                       'time.end=0', '--threads', '1', '--quiet'])
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
        rc, err = run([binary, 'run', case, '-o', os.path.join(work, 'out'), '--threads', '1',
                       '--quiet', '--set', 'resolution=0.02'] + sets +
                      ['--set', 'time.end=2e-7', '--set', 'output.every=1e-7'])
        if not (rc == 0 or (rc in (2, 3) and errors(err) == 1)):
            bad += 1
            print('BAD', it, os.path.basename(case), ' '.join(sets), rc, err.strip()[-300:],
                  flush=True)
    print('keys', len(keys))
    return bad


def main():
    if len(sys.argv) < 5 or sys.argv[2] not in ('cases', 'sets'):
        sys.exit(__doc__)
    binary, mode, seed, n = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    work = sys.argv[5] if len(sys.argv) > 5 else '/tmp/hvsph-fuzz'
    os.makedirs(work, exist_ok=True)
    random.seed(seed)
    bad = fuzz_cases(binary, n, work) if mode == 'cases' else fuzz_sets(binary, n, work,
                                                                        sys.argv[6:])
    print('done', n, 'tries,', bad, 'bad')
    sys.exit(1 if bad else 0)


if __name__ == '__main__':
    main()
