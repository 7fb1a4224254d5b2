#!/bin/bash
# planar porous impact with plate particles ~31x heavier than the debris' (W.P.3's second bumper)
cd /tmp/s51/planar
mk() { # name density debris_spacing plate_spacing
cat > $1.yaml <<Y
name: porous-heavy
materials:
  al: {library: al-alloy, strength: {yield: 0}}
domain:
  min: [-8 mm, 0, 0]
  max: [10 mm, 3 mm, 3 mm]
  boundary: {x: open, y: periodic, z: periodic}
bodies:
  - name: debris
    material: al
    shape: {type: box, min: [-8 mm, 0, 0], max: [0, 3 mm, 3 mm]}
    spacing: $3 mm
    density: $2 kg/m3
    damage: 1
    velocity: [7 km/s, 0, 0]
  - name: plate
    material: al
    shape: {type: box, min: [0, 0, 0], max: [10 mm, 3 mm, 3 mm]}
    spacing: $4 mm
sph:
  viscosity: {alpha: 1.0, beta: 2.0}
time:
  end: 0.8 us
output:
  every: 0.05 us
  csv: true
  vtu: false
Y
}
mk h10 278 0.333333 0.5
mk h03 83.4 0.5 0.5
mk e10 278 0.2 0.1
for c in h10 h03; do /tmp/s51/hvsph-new run $c.yaml -o r-$c --threads 1 -q > r-$c.log 2>&1; done
