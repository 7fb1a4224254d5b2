#!/bin/sh
# Session 47: start 2.4 on the core that bumper-3 frees. From the repository root.
while pgrep -f "only bumper-3" > /dev/null; do sleep 10; done
exec sh docs/runs/s47/whipple-steel.sh
