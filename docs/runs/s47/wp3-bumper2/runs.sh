#!/bin/sh
# Session 47: W.P.3's second bumper with one, two and three particle layers.
# Usage (from the repository root): sh docs/runs/s47/wp3-bumper2/runs.sh one|two|three
# Each lane on 1 thread, two at a time. Results in out/s47/b2-LANE. The lane three was
# stopped by SIGINT at 9.80 us (continue: ./build/hvsph restart out/s47/b2-three).
set -e
lane=$1
if [ "$lane" = one ]; then
    ./build/hvsph run docs/runs/s47/wp3-bumper2/one-layer.yaml -o out/s47/b2-one --threads 1
elif [ "$lane" = two ]; then
    ./build/hvsph run docs/runs/s47/wp3-bumper2/two-layer.yaml -o out/s47/b2-two --threads 1
elif [ "$lane" = three ]; then
    ./build/hvsph run docs/runs/s47/wp3-bumper2/three-layer.yaml -o out/s47/b2-three --threads 1
else
    echo "usage: $0 one|two|three" >&2; exit 1
fi
