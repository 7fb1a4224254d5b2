#!/bin/sh
# Session 54: docs/img/val54_ws_pieces_40us.png, §2.4 at resolution 0.3 at 40 us, cut at
# z = 0 (the particles within 1.5 mm of the symmetry plane, seen along z), with the paper's
# rule, split: crack, and split: crack with the 4340 strain to failure. From the repository root.
H=${HVSPH:-out/s54/hvsph}
for r in rule crack crackef; do
  $H render out/s54/frag-$r/whipple-steel/particles_00008.csv -o out/s54/cut-$r.png --mode particles \
    --axis z --box 190mm,222mm,-16mm,16mm,0,1.5mm --no-mirror --size 600
done
/usr/bin/python3 - <<'PY'
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
import matplotlib.image as im
fig, ax = plt.subplots(1, 3, figsize=(15, 5.4))
for a, r, t in zip(ax, ['rule', 'crack', 'crackef'],
                   ["the paper's rule (Tresca splitting)", "split: crack",
                    "split: crack, 4340's strain to failure"]):
    a.imshow(im.imread('out/s54/cut-%s.png' % r))
    a.set_axis_off()
    a.set_title(t)
plt.tight_layout()
plt.savefig('docs/img/val54_ws_pieces_40us.png', dpi=72)
PY
