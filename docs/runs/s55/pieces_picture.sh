#!/bin/sh
# Session 55: docs/img/val55_ws_tau.png, §2.4 at resolution 0.3, the paper's rule and a time
# to failure (tau = 0.3 and 1 us) on the projectile's steel: the particles within 3 mm of
# the symmetry plane, seen along z, at 30 us (the debris in flight) and at 46 us (the
# backwall). Needs the runs of ws-tau.sh, ws-tau-46.sh and ws-rule-46.sh. From the
# repository root.
H=${HVSPH:-out/s55/hvsph}
for r in rule tau-0.3 tau-1; do
  d=out/s55/$r/whipple-steel
  [ $r = rule ] && d=out/s54/frag-rule/whipple-steel
  $H render $d/particles_00006.csv -o out/s55/cut30-$r.png --mode particles \
    --axis z --box 110mm,190mm,-30mm,30mm,0,3mm --no-mirror --size 600
  $H render $d/particles_00014.csv -o out/s55/cut46-$r.png --mode particles \
    --axis z --box 185mm,225mm,-15mm,15mm,0,3mm --no-mirror --size 600
done
/usr/bin/python3 - <<'PY'
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
import matplotlib.image as im
fig, ax = plt.subplots(2, 3, figsize=(15, 9.6))
for j, (r, t) in enumerate([('rule', "the paper's rule (Tresca splitting at once)"),
                            ('tau-0.3', 'projectile: time to failure 0.3 us'),
                            ('tau-1', 'projectile: time to failure 1 us')]):
    for i, when in enumerate(['30', '46']):
        a = ax[i, j]
        a.imshow(im.imread('out/s55/cut%s-%s.png' % (when, r)))
        a.set_axis_off()
        a.set_title('%s, %s us' % (t, when), fontsize=10)
plt.tight_layout()
plt.savefig('docs/img/val55_ws_tau.png', dpi=72)
PY
