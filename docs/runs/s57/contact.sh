# W.P.1 at resolution 0.2 to 31 us, then on to 40 us with CSV snapshots every 0.25 us: the
# debris reaching the backwall (docs/validation.md, Session log, session 57).
# Analysis: /usr/bin/python3 docs/runs/s57/contact.py out/s57/wp1 > contact.out
set -e
B=${HVSPH:-build/hvsph}
$B run examples/paper/wp1.yaml -o ${OUT:-out/s57/wp1} --threads 2 --quiet --set resolution=0.2 --set time.end="31 us" --set output.every="31 us"
$B restart ${OUT:-out/s57/wp1} --threads 2 --quiet --set time.end="40 us" --set output.every="0.25 us" --set output.csv=true
