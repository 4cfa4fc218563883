#!/usr/bin/env bash
# `simeco skeleton` and `simeco infer` end to end: a tree's skeleton, the grammars inferred from it and what they
# regrow, the imports, and malformed skeletons refused with nothing written. Usage: skeleton_test.sh SIMECO SOURCE_DIR
set -u
simeco=$1
source_dir=$2
. "$(dirname "$0")/checks.sh"

tree="$source_dir/grammars/abop/fig2.7-sympodial.l"
out=$("$simeco" skeleton "$tree" -o "$work/tree.json")
check "skeleton exits 0 ($out)" $?
python3 -c "
import json, sys
d = json.load(open('$work/tree.json'))
stems = d['plants'][0]['stems']
sys.exit(0 if len(stems) > 100 and stems[0]['parent'] == -1 and all(len(s['points']) >= 2 for s in stems) else 1)"
check "the skeleton's JSON has stems with parents and points" $?
segments=$(echo "$out" | sed -n 's/.* \([0-9]*\) segments.*/\1/p')

"$simeco" skeleton "$tree" -o "$work/stats.json" --stats >"$work/stats.txt"
grep -q "^level  internodes" "$work/stats.txt" && [ "$(wc -l <"$work/stats.txt")" -gt 5 ]
check "--stats prints the levels" $?

inferred=$("$simeco" infer "$work/tree.json" --describe "alternate, ovate, tree" -o "$work/tree.eco")
check "infer writes a SimEco script ($inferred)" $?
levels=$(echo "$inferred" | sed -n 's/.* in \([0-9]*\) levels.*/\1/p')
again=$("$simeco" skeleton "$work/tree.eco" -n "$levels" -o "$work/again.json")
echo "$again" | grep -q " $segments segments"
check "derived as many steps as it has levels ($levels), the script regrows the skeleton's $segments segments" $?
grown=$("$simeco" skeleton "$work/tree.eco" -o "$work/grown.json")
[ "$(echo "$grown" | sed -n 's/.* \([0-9]*\) segments.*/\1/p')" -gt "$segments" ]
check "derived to its DerivationLength, its prediction rules grow it on ($grown)" $?
"$simeco" infer "$work/tree.json" --initial-only -o "$work/initial.eco" >/dev/null &&
  "$simeco" skeleton "$work/initial.eco" -o "$work/initial.json" | grep -q " $segments segments"
check "the initial state alone regrows the skeleton at its DerivationLength" $?

"$simeco" infer "$work/tree.json" -o "$work/tree.l" >/dev/null && [ -s "$work/tree.l" ] && [ -s "$work/tree.v" ]
check "infer -o tree.l writes the L-system and its view file" $?
again=$("$simeco" skeleton "$work/tree.l" -o "$work/again-l.json")
echo "$again" | grep -q " $segments segments"
check "the L-system regrows the skeleton's segments ($again)" $?

"$simeco" skeleton "$tree" -o "$work/tree-views.svg" >/dev/null &&
  "$simeco" skeleton "$tree" -o "$work/tree.obj" >/dev/null
check "skeleton writes three views and OBJ polylines" $?
"$simeco" infer "$work/tree-views.svg" --initial-only -o "$work/views-tree.eco" >/dev/null
again=$("$simeco" skeleton "$work/views-tree.eco" -o "$work/again-views.json")
echo "$again" | grep -q " $segments segments"
check "the grammar inferred from its three views regrows the skeleton's segments ($again)" $?

cat >"$work/views.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg">
  <g id="front"><polyline data-stem="0" points="0,0 0,-2"/>
    <polyline data-stem="1" data-parent="0" points="0,-1 1,-2"/></g>
  <g id="side"><polyline data-stem="0" points="0,0 0,-2"/>
    <polyline data-stem="1" points="0,-1 0.5,-2"/></g>
  <g id="top"><polyline data-stem="0" points="0,0 0,0.001"/><polyline data-stem="1" points="0,0 1,0.5"/></g>
</svg>
SVG
"$simeco" infer "$work/views.svg" --describe "對生 卵形 灌木" -o "$work/views.eco" >/dev/null
check "infer reads three views drawn as SVG" $?

printf 'v 0 0 0\nv 0 1 0\nv 0 2 0\nv 1 2 0\nl 1 2 3\nl 3 4\n' >"$work/small.obj"
"$simeco" infer "$work/small.obj" -o "$work/obj.eco" >/dev/null
check "infer reads OBJ polylines" $?

# Malformed skeletons: exit 2, the place and what is wrong, and no grammar written.
bad() { # NAME FILE EXPECTED-MESSAGE-PART
  rm -f "$work/bad.eco"
  "$simeco" infer "$2" -o "$work/bad.eco" >/dev/null 2>"$work/err.txt"
  local code=$?
  [ $code -eq 2 ] && [ ! -e "$work/bad.eco" ] && grep -q "$3" "$work/err.txt"
  check "$1 is refused (code $code: $(head -c 200 "$work/err.txt"))" $?
}
printf '%s\n' '{"plants": [{"stems": [{"id": 0, "parent": 1, "points": [[0,0,0],[0,1,0]]},' \
  '{"id": 1, "parent": 0, "points": [[0,1,0],[0,2,0]]}]}]}' >"$work/cycle.json"
bad "a cycle" "$work/cycle.json" "loop back"
printf '%s\n' '{"plants": [{"stems": [{"id": 0, "points": [[0,0,0],[0,1,0]]},' \
  '{"id": 1, "points": [[5,0,0],[5,1,0]]}]}]}' >"$work/apart.json"
bad "a plant in two pieces" "$work/apart.json" "not connected"
printf '{"plants": [{"stems": [{"id": 0, "points": [[0,0,0],[0,0,0]]}]}]}\n' >"$work/zero.json"
bad "a zero-length stem" "$work/zero.json" "coincide"
printf '{"plants": [{"stems": [{"id": 0, "points": [[0,0,0],[0,NaN,0]]}]}]}\n' >"$work/nan.json"
bad "NaN" "$work/nan.json" "nan.json:1:"
printf '{"plants": [{"stems": [{"id": 0, "points": [[0,0,0],[0,1e999,0]]}]}]}\n' >"$work/huge.json"
bad "a number beyond a double" "$work/huge.json" "overflow"
printf 'v 0 0 0\nv 0 1 0\nl 1 x\n' >"$work/bad.obj"
bad "an OBJ with a bad index" "$work/bad.obj" "bad.obj:3:5: error"
"$simeco" infer "$work/tree.json" --describe "purple" -o "$work/bad.eco" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && [ ! -e "$work/bad.eco" ] && grep -q "unknown word 'purple'" "$work/err.txt"
check "an unknown description word is refused (code $code)" $?

finish_checks
