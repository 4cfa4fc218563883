#!/usr/bin/env bash
# End-to-end checks of the simeco command line. Usage: cli_test.sh SIMECO SOURCE_DIR
set -u
simeco=$1
source_dir=$2
. "$(dirname "$0")/checks.sh"

"$simeco" --help >"$work/help.txt" 2>&1
check "--help exits 0" $?
grep -q "derive" "$work/help.txt"
check "--help lists derive" $?

"$simeco" derive --help >/dev/null 2>&1
check "derive --help exits 0" $?

cat >"$work/algae.l" <<'L'
Lsystem: 1
derivation length: 5
Axiom: A
A --> AB
B --> A
endlsystem
L
out=$("$simeco" derive "$work/algae.l")
check "derive exits 0" $?
[ "$out" = "ABAABABAABAAB" ]
check "derive prints the string (got '$out')" $?

out=$("$simeco" derive "$work/algae.l" -n 2)
[ "$out" = "ABA" ]
check "-n overrides the derivation length (got '$out')" $?

"$simeco" derive "$work/algae.l" --format stats >"$work/stats.txt"
check "--format stats exits 0" $?
grep -q "^modules: 13$" "$work/stats.txt" && grep -q "^  A 8$" "$work/stats.txt" && grep -q "^max branch depth: 0$" "$work/stats.txt"
check "stats report counts" $?

"$simeco" derive "$work/algae.l" --format json >"$work/stats.json"
check "--format json exits 0" $?
python3 -c "import json,sys; d=json.load(open('$work/stats.json')); sys.exit(0 if d['modules']==13 and d['symbols']['B']==5 else 1)"
check "json report is valid and counts modules" $?

out=$("$simeco" derive "$work/algae.l" --plants 3 | wc -l)
[ "$out" -eq 3 ]
check "--plants prints one line per plant" $?

"$simeco" derive "$source_dir/scenes/garden.eco" >"$work/garden-cpu.txt" 2>/dev/null
[ "$(wc -l <"$work/garden-cpu.txt")" -eq 3 ] && [ "$(sort -u "$work/garden-cpu.txt" | wc -l)" -eq 3 ]
check "a scene of three species derives one distinct plant of each" $?
"$simeco" derive "$source_dir/scenes/garden.eco" --backend gpu --plants 6 >"$work/garden-gpu.txt" 2>/dev/null
"$simeco" derive "$source_dir/scenes/garden.eco" --plants 6 >"$work/garden-cpu6.txt" 2>/dev/null
[ -s "$work/garden-gpu.txt" ] && cmp -s "$work/garden-gpu.txt" "$work/garden-cpu6.txt"
check "the GPU derives the scene's species in one pass as the CPU does" $?

out=$("$simeco" derive "$work/algae.l" --backend gpu --profile 2>"$work/profile.txt")
[ "$out" = "ABAABABAABAAB" ]
check "--profile leaves the string on stdout (got '$out')" $?
awk '$1 == "derive/match" && $2 == 5 { m = 1 } $1 == "derive/write" && $2 == 5 { w = 1 } $1 == "total" && $2 > 0 { t = 1 }
     END { exit !(m && w && t) }' "$work/profile.txt"
status=$?
check "--profile times each kernel once per step ($(tr '\n' ' ' <"$work/profile.txt"))" $status

printf 'Lsystem: 1\nderivation length: 1\nAxiom: A(1)\nA(x) --> A(y)\nendlsystem\n' >"$work/bad.l"
"$simeco" derive "$work/bad.l" >"$work/out.txt" 2>"$work/err.txt"
code=$?
[ $code -eq 2 ]
check "bad input exits 2 (got $code)" $?
grep -q "^$work/bad.l:4:12: error: undefined name 'y'$" "$work/err.txt"
status=$?
check "error in file:line:col form ($(cat "$work/err.txt"))" $status
[ ! -s "$work/out.txt" ]
check "no partial output on error" $?

head -c 3000 /dev/urandom >"$work/junk.l"
timeout 20 "$simeco" derive "$work/junk.l" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ]
check "binary junk exits 2 (got $code)" $?

"$simeco" derive "$work/missing.l" >/dev/null 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "cannot open file" "$work/err.txt"
check "missing file is reported" $?

printf 'Lsystem: 1\nderivation length: 60\nAxiom: F\nF --> FF\nendlsystem\n' >"$work/runaway.l"
timeout 60 "$simeco" derive "$work/runaway.l" --max-modules 100000 >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 1 ] && grep -q "module budget of 100000" "$work/err.txt"
check "module budget ends runaway growth with a clear error (code $code)" $?

# A derivation of 10^9 steps ends at its time limit with a clear error, on either engine.
printf 'Lsystem: 1\nderivation length: 1000000000\nAxiom: A\nA --> A\nendlsystem\n' >"$work/forever.l"
for backend in cpu gpu; do
  timeout 60 "$simeco" derive "$work/forever.l" --backend $backend --max-seconds 1 >/dev/null 2>"$work/err.txt"
  code=$?
  [ $code -eq 1 ] && grep -q "ran past its time limit of 1 s in step" "$work/err.txt"
  status=$?
  check "a derivation past --max-seconds ends with a clear error ($backend, code $code: $(cat "$work/err.txt"))" $status
done

"$simeco" derive "$work/algae.l" --format nonsense >/dev/null 2>&1
[ $? -eq 2 ]
check "bad option exits 2" $?

"$simeco" devices >"$work/devices.txt" 2>&1
status=$?
check "devices lists Vulkan devices ($(head -c 300 "$work/devices.txt"))" $status

"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" -n 4 --plants 4 --size 160x120 -o "$work/field.exr" \
  --png "$work/field.png" >"$work/render.txt" 2>&1
[ -s "$work/field.exr" ] && [ -s "$work/field.png" ] && grep -q "4 plants" "$work/render.txt" &&
  [ "$(head -c 4 "$work/field.exr" | od -An -tx1 | tr -d ' ')" = "762f3101" ] &&
  [ "$(head -c 8 "$work/field.png" | od -An -tx1 | tr -d ' ')" = "89504e470d0a1a0a" ]
status=$?
check "render writes the EXR and the PNG of a field ($(head -c 300 "$work/render.txt"))" $status

# The light grid of the field drawn: a layer seen from above and one from the front beside the image, the shade in it.
"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" -n 4 --plants 4 --size 160x120 -o "$work/lit.png" \
  --light-slice 1 --light-section 0 --light-volume --occupancy-slice 1 >"$work/lit.txt" 2>&1
python3 - "$work" <<'PY'
import struct, sys
def png_size(name):
    data = open(f"{sys.argv[1]}/{name}", "rb").read(24)
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{name} is a PNG"
    return struct.unpack(">II", data[16:24])
assert png_size("lit.png") == (160, 120)
(slice_w, slice_h), (section_w, section_h) = png_size("lit-light.png"), png_size("lit-light-section.png")
assert slice_w == section_w and slice_h > 0 and section_h > 0, (slice_w, slice_h, section_w, section_h)
assert png_size("lit-occupancy.png") == (slice_w, slice_h)
PY
ok=$?
check "render writes the light grid's views ($(head -c 300 "$work/lit.txt"))" $ok

# A cloud of the library in another palette, cut from paper; the palette's entry 0 is the background.
"$simeco" render "$source_dir/grammars/clouds/head-c1a.l" --size 80x60 --style paper-cut \
  --colormap "$source_dir/grammars/clouds/palettes/gold-on-red.map" -o "$work/cut.png" >"$work/cut.txt" 2>&1
[ -s "$work/cut.png" ]
check "render draws a cloud in a colour map given on the command line ($(head -c 300 "$work/cut.txt"))" $?

# Antialiased: the frame drawn at twice the size and brought to the size asked for.
"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" -n 4 --size 96x72 --antialias 2 -o "$work/aa.png" \
  >"$work/aa.txt" 2>&1
PYTHONPATH="$(dirname "$0")" python3 -c "
import sys
from png_pixels import read_png
width, height, rows = read_png(sys.argv[1])
assert (width, height) == (96, 72), (width, height)
assert len({p for row in rows for p in row}) > 20  # edges blend the organs into the background
" "$work/aa.png" && ! grep -qi validation "$work/aa.txt"
check "render --antialias 2 draws a smoothed frame of the size asked for ($(head -c 300 "$work/aa.txt"))" $?

# The cloud's growth in four frames: more of it drawn in each, every one framed alike.
"$simeco" render "$source_dir/grammars/clouds/head-c1a.l" --frames 4 --size 80x60 -o "$work/grow.png" \
  >"$work/grow.txt" 2>&1
PYTHONPATH="$(dirname "$0")" python3 - "$work" <<'PY'
import sys
from png_pixels import read_png
def pixels(name):
    return read_png(f"{sys.argv[1]}/{name}")[2]
drawn = []
for k in range(1, 5):
    rows = pixels(f"grow-{k:05}.png")
    background = rows[0][0]
    drawn.append(sum(p != background for row in rows for p in row))
assert drawn[0] < drawn[3] and drawn == sorted(drawn) and drawn[3] > 80 * 60 // 20, drawn
PY
status=$?
[ $status -eq 0 ] && [ ! -e "$work/grow-00005.png" ] && grep -q "in 4 frames" "$work/grow.txt"
check "render --frames draws the growth, more in each frame ($(head -c 300 "$work/grow.txt"))" $?

"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" --background colormap -o "$work/nomap.png" \
  >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && [ ! -e "$work/nomap.png" ] && grep -q "no colour map" "$work/err.txt"
check "a colour map's background for a model without one is bad input (code $code)" $?

printf 'render style: sketchy\n' >"$work/algae.v"
"$simeco" render "$work/algae.l" -o "$work/sketchy.png" >/dev/null 2>"$work/err.txt"
code=$?
rm "$work/algae.v"
[ $code -eq 2 ] && [ ! -e "$work/sketchy.png" ] && grep -q "algae.v:1:15: error: render style" "$work/err.txt"
check "a view file's unknown render style is reported at its line and column (code $code)" $?

"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" --size 0x5 -o "$work/bad.png" >/dev/null 2>&1
code=$?
[ $code -ne 0 ] && [ ! -e "$work/bad.png" ] && [ -z "$(ls "$work" | grep -i 'bad.*tmp')" ]
check "render refuses a bad size and writes nothing (code $code)" $?

# Multisampled unless told otherwise: a paper cut's flat colours blend along their edges; one sample a pixel keeps
# them flat. A count of samples the device lacks is refused by name, and nothing is written.
for msaa in default 1; do
  option=""; [ $msaa = 1 ] && option="--msaa 1"
  "$simeco" render "$source_dir/grammars/abop/fig1.24d.l" -n 4 --size 96x72 --style paper-cut $option \
    -o "$work/ms-$msaa.png" >"$work/ms-$msaa.txt" 2>&1
done
PYTHONPATH="$(dirname "$0")" python3 -c "
import sys
from png_pixels import read_png
colours = [len({p for row in read_png(name)[2] for p in row}) for name in sys.argv[1:]]
assert colours[1] < 8 and colours[0] > colours[1] + 4, colours  # edges: a quarter, a half, three quarters
" "$work/ms-default.png" "$work/ms-1.png"
check "render multisamples by default, and --msaa 1 draws a pixel from one sample ($(cat "$work/ms-default.txt"))" $?
"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" -n 2 --size 48x36 --msaa 16 -o "$work/ms16.png" \
  >"$work/ms16.txt" 2>&1
code=$?
if [ $code -eq 0 ]; then [ -s "$work/ms16.png" ]; else
  [ ! -e "$work/ms16.png" ] && grep -q "cannot draw 16 samples a pixel: the device .* draws 1" "$work/ms16.txt"; fi
check "render draws 16 samples a pixel where the device has them, else says which it has ($(cat "$work/ms16.txt"))" $?

"$simeco" render "$source_dir/grammars/abop/fig1.24d.l" --size 20x -o "$work/bad.png" >/dev/null 2>&1
code=$?
[ $code -eq 2 ]
check "a malformed size is bad input: exit code 2 (code $code)" $?

"$simeco" render "$source_dir/grammars/abop/fig1.24a.l" -n 2 --size 80x60 --shadows none -o "$work/half.exr" \
  --png "$work/no-such-folder/half.png" >/dev/null 2>&1
code=$?
[ $code -ne 0 ] && [ -z "$(ls "$work" | grep half)" ]
check "render writes both of its images or neither (code $code)" $?

# fig. 1.24a at two steps: 25 stems a plant, 50 vertices a stem.
"$simeco" export "$source_dir/grammars/abop/fig1.24a.l" -n 2 --plants 2 -o "$work/plants.obj" >"$work/export.txt" 2>&1
[ "$(grep -c '^v ' "$work/plants.obj")" -eq 2500 ] && [ "$(grep -c '^vn ' "$work/plants.obj")" -eq 2500 ] &&
  [ "$(grep -c '^o plant_' "$work/plants.obj")" -eq 2 ] && grep -q "2 plants" "$work/export.txt"
status=$?
check "export writes the OBJ of a field, one object per plant ($(head -c 300 "$work/export.txt"))" $status

"$simeco" export "$source_dir/grammars/abop/fig1.24a.l" -o "$work/plants.stl" >/dev/null 2>"$work/err.txt"
code=$?
[ $code -eq 2 ] && [ ! -e "$work/plants.stl" ] && grep -q "obj, .ply or .gltf" "$work/err.txt"
check "export refuses another extension and writes nothing (code $code)" $?

"$simeco" export "$source_dir/grammars/clouds/oriental-clouds.l" --backend cpu -o "$work/clouds.gltf" >/dev/null 2>&1
python3 -c "import json,sys; d=json.load(open('$work/clouds.gltf')); sys.exit(0 if d['asset']['version']=='2.0' and d['meshes'] else 1)"
check "export writes a glTF with its meshes" $?

# The default module budget counts what each engine allocates per module (stream/derive_options.h: 32 bytes on
# the CPU, 114 on the device and 17 on the host at one parameter slot): a derivation's peak memory above a tiny
# one's stays within its modules times those bytes, so the budget never lets a derivation run out of memory.
# Under AddressSanitizer the heap's redzones and quarantine are the sanitizer's, not the engines': not checked there.
printf 'Lsystem: 1\nderivation length: 22\nAxiom: A\nA --> AA\nendlsystem\n' >"$work/doubling.l"
budgets="cpu:32 gpu:131"
if ldd "$simeco" 2>/dev/null | grep -q libasan; then
  echo "note: $simeco is built with AddressSanitizer; the memory bound per module is not checked"
  budgets=""
fi
for backend in $budgets; do
  python3 - "$simeco" "$work/doubling.l" "${backend%%:*}" "${backend##*:}" >"$work/memory.txt" 2>&1 <<'PY'
import resource, subprocess, sys
simeco, grammar, backend, bytes_per_module = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
def peak(steps):
    out = subprocess.run([simeco, "derive", grammar, "-n", str(steps), "--backend", backend, "--format", "stats"],
                         check=True, capture_output=True, text=True).stdout
    # The children's peak so far: the largest of the runs, so the smaller runs first.
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024, int(out.split("modules: ")[1].split()[0])
base, _ = peak(1)
top, modules = peak(22)
print(f"{backend}: {modules} modules, {(top - base) / modules:.1f} bytes a module above a tiny derivation "
      f"(budget assumes {bytes_per_module})")
sys.exit(0 if modules == 1 << 22 and top - base <= modules * bytes_per_module else 1)
PY
  status=$?
  check "the module budget's bytes per module bound the peak memory ($(cat "$work/memory.txt"))" $status
done

# A parameter that overflows to infinity draws a stem of infinite length: every output refuses it alike.
printf 'Lsystem: 1\nderivation length: 2\nAxiom: A(1e30)\nA(x) --> F(1)[+F(x * 1e30)]F(1)A(x)\nendlsystem\n' \
  >"$work/infinite.l"
for backend in gpu cpu; do
  for output in infinite.exr infinite.obj infinite.ply infinite.gltf; do
    command=export
    [ "$output" = infinite.exr ] && command=render
    "$simeco" "$command" "$work/infinite.l" --backend $backend -o "$work/$output" >/dev/null 2>"$work/err.txt"
    code=$?
    [ $code -eq 1 ] && [ -z "$(ls "$work" | grep 'infinite\.[eopg]')" ] && grep -q "not a finite number" "$work/err.txt"
    check "$command -o $output --backend $backend refuses non-finite geometry, writes nothing (code $code)" $?
  done
done

finish_checks
