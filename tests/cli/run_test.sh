#!/usr/bin/env bash
# End-to-end checks of `simeco run`: a field grown tick by tick writes its statistics, its plants and its frames;
# the same seed gives the same files, either backend the same field; bad input writes nothing.
# Usage: run_test.sh SIMECO SOURCE_DIR
set -u
simeco=$1
source_dir=$2
. "$(dirname "$0")/checks.sh"
garden="$source_dir/scenes/garden.eco"

grow() { # grow OUT [OPTIONS...]: four garden plants for 12 simulated seconds, a tick a second
  local out=$1
  shift
  "$simeco" run "$garden" --plants 4 --dt 1 --time 12 --size 96x72 --out "$out" "$@" >"$out.txt" 2>&1
}

grow "$work/a" --frames 6
code=$?
[ $code -eq 0 ]
ok=$?
check "run exits 0 (got $code: $(head -c 300 "$work/a.txt"))" $ok
for f in stats.jsonl plants.csv final.exr final.png frame-00006.png frame-00012.png; do
  [ -s "$work/a/$f" ]
  check "run writes $f" $?
done
[ "$(find "$work/a" -type f | wc -l)" -eq 6 ]
ok=$?
check "run writes nothing else ($(ls "$work/a" | tr '\n' ' '))" $ok

python3 - "$work/a" <<'PY'
import csv, json, sys
out = sys.argv[1]
lines = [json.loads(l) for l in open(f"{out}/stats.jsonl")]
assert len(lines) == 12, f"{len(lines)} lines for 12 ticks"
for k, line in enumerate(lines):
    for key in ("time", "tick", "plants", "modules", "organs", "leaf_area", "light", "derived"):
        assert key in line, f"line {k} lacks {key}"
    assert line["tick"] == k and abs(line["time"] - (k + 1)) < 1e-9 and line["plants"] == 4, line
# The plants derive a step every DeriveTime (3 s): the string grows; the leaves grow in between.
assert lines[-1]["modules"] > lines[0]["modules"], (lines[0], lines[-1])
assert sum(l["derived"] for l in lines) >= 4 * 3, "each plant derived every 3 s"
assert lines[-1]["leaf_area"] > 0 and lines[-1]["organs"] > 0, lines[-1]
rows = list(csv.reader(open(f"{out}/plants.csv")))
assert rows[0] == ["plant", "species", "x", "z", "alive", "modules", "height", "leaf_area", "light"], rows[0]
assert [r[0] for r in rows[1:]] == ["0", "1", "2", "3"], rows
assert rows[1][1] == "Lantan camara" and rows[4][1] == "Lantan camara", "the species take turns"
assert sum(int(r[5]) for r in rows[1:]) == lines[-1]["modules"], "the plants' modules add up"
assert all(float(r[6]) > 0 for r in rows[1:]), "every plant grew"
# Plants 0 and 3 are of one species at different places: their random streams differ.
assert (rows[1][2], rows[1][3]) != (rows[4][2], rows[4][3]) and rows[1][5:] != rows[4][5:], (rows[1], rows[4])
PY
check "stats.jsonl has a line per tick and plants.csv a row per plant, as documented" $?

grow "$work/b" --frames 6
cmp -s "$work/a/stats.jsonl" "$work/b/stats.jsonl" && cmp -s "$work/a/plants.csv" "$work/b/plants.csv"
check "the same seed grows the same field" $?

grow "$work/c" --seed 7
! cmp -s "$work/a/plants.csv" "$work/c/plants.csv"
check "another seed grows another field" $?

grow "$work/cpu" --backend cpu
python3 - "$work/a" "$work/cpu" <<'PY'
import json, sys
gpu = [json.loads(l) for l in open(f"{sys.argv[1]}/stats.jsonl")]
cpu = [json.loads(l) for l in open(f"{sys.argv[2]}/stats.jsonl")]
assert len(gpu) == len(cpu)
for g, c in zip(gpu, cpu):
    assert (g["modules"], g["organs"], g["derived"]) == (c["modules"], c["organs"], c["derived"]), (g, c)
    assert abs(g["leaf_area"] - c["leaf_area"]) <= 1e-4 * max(1.0, c["leaf_area"]), (g, c)
PY
check "the device grows the field as the CPU references do" $?

(cd "$work" && "$simeco" run --plants 3 --time 4 --size 64x48 >"$work/default.txt" 2>&1)
[ -s "$work/run/final.png" ] && grep -q '^0,"Lantan camara",' "$work/run/plants.csv" &&
  grep -q '^2,"Oxalis corniculata",' "$work/run/plants.csv" && [ "$(wc -l <"$work/run/stats.jsonl")" -eq 4 ]
ok=$?
check "with no scene, run grows the built-in garden into ./run ($(head -c 200 "$work/default.txt"))" $ok

printf 'EcoSystem 1.0 "Bad" {\n  Plant "P" {\n    Stem { Default { GrowRate = ; } }\n  }\n}\n' >"$work/bad.eco"
"$simeco" run "$work/bad.eco" --out "$work/bad" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && grep -q "^$work/bad.eco:3:[0-9]*: error: " "$work/err.txt"
ok=$?
check "a bad scene exits 2 with file:line:col (code $code: $(head -c 200 "$work/err.txt"))" $ok
[ -z "$(ls -A "$work/bad" 2>/dev/null)" ]
check "a bad scene writes nothing" $?

# Saved at 6 s and resumed to 18 s, on either backend: the field ends as the uninterrupted one on that backend does
# (12 plants, so that their random draws after the resumption decide something). The two backends' floats may
# differ in their last bits, which plants.csv's nine digits can show.
field() { # field OUT TIME [OPTIONS...]
  local out=$1 time=$2
  shift 2
  "$simeco" run "$garden" --plants 12 --dt 1 --time "$time" --size 96x72 --out "$out" "$@" >"$out.txt" 2>&1
}
for backend in gpu cpu; do
  field "$work/whole-$backend" 18 --backend $backend
  field "$work/first-$backend" 6 --backend $backend --save "$work/state-$backend.bin"
done
[ -s "$work/state-gpu.bin" ] && [ -s "$work/whole-gpu/plants.csv" ] && [ ! -e "$work/first-gpu/state-gpu.bin" ]
check "run --save writes the state where it is asked" $?
for backend in gpu cpu; do
  "$simeco" run --resume "$work/state-$backend.bin" --time 18 --size 96x72 --backend $backend \
    --out "$work/rest-$backend" >"$work/rest-$backend.txt" 2>&1
  [ "$(wc -l <"$work/rest-$backend/stats.jsonl")" -eq 12 ] &&
    cmp -s <(tail -1 "$work/whole-$backend/stats.jsonl") <(tail -1 "$work/rest-$backend/stats.jsonl") &&
    cmp -s "$work/whole-$backend/plants.csv" "$work/rest-$backend/plants.csv"
  ok=$?
  check "resumed on the $backend backend, the field ends as before ($(head -c 200 "$work/rest-$backend.txt"))" $ok
done

head -c 300 "$work/state-gpu.bin" >"$work/truncated.bin"
"$simeco" run --resume "$work/truncated.bin" --out "$work/truncated" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && grep -q "^$work/truncated.bin: error: .*truncated" "$work/err.txt" && [ ! -e "$work/truncated" ]
ok=$?
check "a truncated state is refused and nothing written (code $code: $(head -c 200 "$work/err.txt"))" $ok
"$simeco" run "$garden" --resume "$work/state-gpu.bin" --out "$work/both" >/dev/null 2>&1
[ $? -eq 2 ]
check "a scene and a state to resume are refused together" $?

# The meadow: its populations where the scene puts them, the bushes of a cpfg grammar among them.
# Its light grid: a layer of it written as light.png, a vertical one as light-section.png, its holders as
# occupancy.png, the shade in 3D as light-volume.png, and the leaves' light at
# most the open's (SunIntensity 1.1 and 0.3 of SkyLight 1.0) per unit of leaf area.
"$simeco" run "$source_dir/scenes/meadow.eco" --time 4 --size 96x72 --light-slice 1 --light-section 0 --light-volume \
  --occupancy-slice 1 \
  --out "$work/meadow" >"$work/meadow.txt" 2>&1
python3 - "$work/meadow" <<'PY'
import csv, struct, sys
def png_size(name):
    data = open(f"{sys.argv[1]}/{name}", "rb").read(24)
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{name} is a PNG"
    return struct.unpack(">II", data[16:24])
# The slice is the grid seen from above (x by z), the section from the front (x by height): as wide, less high.
(slice_w, slice_h), (section_w, section_h) = png_size("light.png"), png_size("light-section.png")
assert slice_w == section_w and section_h < slice_h, (slice_w, slice_h, section_w, section_h)
assert png_size("light-volume.png") == png_size("final.png") == (96, 72)
assert png_size("occupancy.png") == (slice_w, slice_h)
rows = list(csv.DictReader(open(f"{sys.argv[1]}/plants.csv")))
leafy = [r for r in rows if float(r["leaf_area"]) > 0]
assert leafy and all(0 < float(r["light"]) <= 1.4 * float(r["leaf_area"]) + 1e-3 for r in leafy)
herbs = [r for r in rows if r["species"] == "Meadow herb"]
bushes = [r for r in rows if r["species"] == "Bush"]
assert len(herbs) == round(0.25 * 50 * 30) and len(bushes) == 10, (len(herbs), len(bushes))
assert [r["plant"] for r in rows] == [str(k) for k in range(len(rows))], "plants numbered in order"
assert all(abs(float(r["x"])) <= 25 and abs(float(r["z"]) + 4) <= 15 for r in herbs)
assert all(abs(float(r["x"])) <= 25 and abs(float(r["z"]) - 14) <= 1.5 for r in bushes)
assert all(int(r["modules"]) > 0 for r in rows)
PY
ok=$?
check "the meadow's populations stand in their regions ($(head -c 200 "$work/meadow.txt"))" $ok
"$simeco" run "$source_dir/scenes/meadow.eco" --plants 5 --out "$work/meadow5" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && grep -q "populations" "$work/err.txt" && [ ! -e "$work/meadow5" ]
ok=$?
check "a count of plants for a scene of populations is refused (code $code: $(head -c 200 "$work/err.txt"))" $ok

"$simeco" run "$garden" --dt 0 --out "$work/dt" >/dev/null 2>&1
[ $? -eq 2 ]
check "a tick of no time is refused" $?

finish_checks
