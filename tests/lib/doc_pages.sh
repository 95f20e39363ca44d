# SPDX-License-Identifier: BSD-3-Clause
# What tests/tutorial.sh and tests/gallery.sh check alike on their page (sourced after
# tests/lib/preamble.sh): page_build PAGE builds docs/PAGE.md with tools/gallery.sh into
# $tmp/out (every command block run) and sets d, the folder of its pictures; page_files
# PAGE checks that the page shows every file of examples/PAGE as it is and nothing else,
# that every picture and link of the page was made and is what its name says, that the
# built page shows each, and that the repository's page links no picture it lacks.
page_build() { # PAGE
  bash tools/gallery.sh "$BGDRAW" "$tmp/out" "$1" 2>"$tmp/build.err"
  local st=$?
  check "tools/gallery.sh builds docs/$1.md: $(tail -3 "$tmp/build.err")" $st
  d=$tmp/out/$1
}
page_files() { # PAGE
  local f img bad
  for f in examples/"$1"/*.bg examples/"$1"/*.c examples/"$1"/*.py examples/"$1"/*.yaml; do
    [ -f "$f" ] || continue
    cmp -s "$f" "$d/${f##*/}"; check "docs/$1.md shows $f as it is" $?
  done
  while IFS= read -r f; do
    [ -f "examples/$1/$f" ]; check "the page's model $f is a file of examples/$1" $?
  done < <(grep -o "^<!-- file: $1/[^ ]* -->" "docs/$1.md" | sed "s|^<!-- file: $1/||; s| -->\$||")
  for img in $(grep -o "]($1/[^)]*)" "docs/$1.md" | sed "s|^]($1/||; s|)\$||"); do
    case $img in
      *.png) file "$d/$img" | grep -q 'PNG image data' ;;
      *.pdf) file "$d/$img" | grep -q 'PDF document' ;;
      *.html) grep -q '</html>' "$d/$img" ;;
      *) false ;;
    esac
    check "the page's $img is made" $?
    grep -v '^<!--' "$tmp/out/$1.md" | grep -qF "]($1/$img)"
    check "the built page shows $img" $?
  done
  # every relative link of the built page (and of its HTML) leads to a file: the pages
  # built beside it, the repository's docs for the others
  bad=$(python3 - "$tmp/out" "$1" <<'EOF'
import os, re, sys
out, page = sys.argv[1], sys.argv[2]
for name, pat in ((page + ".md", r"\]\(([^)\s]+)\)"), (page + ".html", r'href="([^"]+)"')):
    path = os.path.join(out, name)
    if not os.path.exists(path):
        continue
    for target in re.findall(pat, open(path, encoding="utf-8").read()):
        if re.match(r"[a-z]+:|#", target):
            continue
        if not os.path.exists(os.path.join(out, target.split("#")[0])):
            print(name + ": " + target)
EOF
)
  [ -z "$bad" ]; check "the built page's links lead to files: ${bad:-all}" $?
  # the repository's page shows no picture and links no file that is not a file of the
  # repository (the built ones are named in comments: docs/gallery.md, "Where the
  # pictures are")
  bad=$(grep -v '^<!--' "docs/$1.md" | grep -o "]($1/[^)]*)" | sed 's/^](//; s/)$//' |
    while read -r img; do [ -f "docs/$img" ] || echo "$img"; done)
  [ -z "$bad" ]; check "docs/$1.md shows or links nothing the repository lacks: ${bad:-none}" $?
}
