#!/usr/bin/env bash
# test_repo_text.sh — the repository speaks of itself as a product (docs/testing.md):
#  1. no tracked text file names a run or a change by a work-period counter: the word
#     is assembled below so that this file does not contain it; runs and changes are
#     named by date and commit;
#  2. every relative link of a tracked Markdown page ([text](path) or ![alt](path),
#     without its #anchor) names a file or folder that exists;
#  3. every picture in docs/img is shown by a page, and the folder stays under 4 MB
#     (a page's pictures, each made by `make figures`; earlier runs' pictures live in
#     git history).
# Needs git and a checkout (a tarball without .git skips with exit 77).
set -u
src=${HVSPH_SOURCE_DIR:?HVSPH_SOURCE_DIR not set}
cd "$src" || exit 1
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || { echo "SKIP: not a git checkout"; exit 77; }
pass=0 fail=0
check() { # check OK MESSAGE [DETAILS]
  if [ "$1" = 0 ]; then pass=$((pass + 1)); echo "  ok    $2"
  else fail=$((fail + 1)); echo "  FAIL  $2"; [ -n "${3:-}" ] && printf '%s\n' "$3" | head -40; fi
}

word="ses""sion"
hits=$(git grep -Iin -w -E "${word}s?" -- . 2>/dev/null)
check "$([ -z "$hits" ] && echo 0 || echo 1)" \
  "no tracked text file names a work period ($(printf '%s' "$hits" | grep -c . ) lines do)" "$hits"

links_py=$(cat <<'PY'
import os, re, sys
link = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)')
for page in sys.argv[1:]:
    text = open(page, encoding="utf-8").read()
    # links inside code blocks and inline code are examples, not links
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    text = re.sub(r"`[^`\n]*`", "", text)
    for m in link.finditer(text):
        target = m.group(1)
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue
        path = os.path.normpath(os.path.join(os.path.dirname(page), target.split("#")[0]))
        if not os.path.exists(path):
            print(f"{page}: {target}")
PY
)
broken=$(git ls-files -z '*.md' | xargs -0 python3 -c "$links_py")
check "$([ -z "$broken" ] && echo 0 || echo 1)" \
  "every relative link of the Markdown pages names a file that exists" "$broken"

unshown=""
for f in $(git ls-files docs/img); do
  b=$(basename "$f")
  git grep -q -F "img/$b" -- '*.md' || unshown+="$f"$'\n'
done
check "$([ -z "$unshown" ] && echo 0 || echo 1)" "every picture in docs/img is shown by a page" "$unshown"
kb=$(git ls-files -z docs/img | xargs -0 du -ck 2>/dev/null | tail -n 1 | cut -f1)
check "$([ "${kb:-0}" -le 4096 ] && echo 0 || echo 1)" "docs/img holds ${kb:-0} kB, at most 4096"

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
