#!/bin/sh
# Session 47, second part: the first cloud's spacing (cloud-040.yaml, cloud-016.yaml),
# one lane after the other on 1 thread. From the repository root; results in
# out/s47/b2-cloudNNN.
set -e
for tag in 040 016; do
    ./build/hvsph run docs/runs/s47/wp3-bumper2/cloud-$tag.yaml -o out/s47/b2-cloud$tag --threads 1
done
