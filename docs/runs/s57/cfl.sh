# The debris's first contact with W.P.1's backwall (resolution 0.2) with the case's CFL number
# 0.3 and with 0.1, CSV snapshots every 0.05 us over 31-33 us (docs/validation.md,
# Session log, session 57). Analysis: for c in 0.3 0.1; do /usr/bin/python3
# docs/runs/s57/contact.py out/s57/wp1-cfl$c; done > cfl.out
set -e
B=${HVSPH:-build/hvsph}
O=${OUT:-out/s57}
$B run examples/paper/wp1.yaml -o $O/wp1-31 --threads 2 --quiet --set resolution=0.2 --set time.end="31 us" --set output.every="31 us"
for c in 0.3 0.1; do
  rm -rf $O/wp1-cfl$c && cp -r $O/wp1-31 $O/wp1-cfl$c
  $B restart $O/wp1-cfl$c --threads 2 --quiet --set time.end="33 us" --set output.every="0.05 us" --set output.csv=true --set output.vtu=false --set time.cfl=$c
done
