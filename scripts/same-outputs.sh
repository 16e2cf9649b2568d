#!/usr/bin/env bash
# Refactoring check: runs the same meshprep commands with two binaries and says whether every output
# is byte-identical. Each command's output files, stdout, stderr and exit code (NAME.stdout,
# NAME.stderr, NAME.rc) land in WORKDIR/old and WORKDIR/new; then every file is compared with cmp.
# A file that differs is compared again with its wall-clock figures masked (JSON "seconds",
# "time_seconds", "tetgen_seconds"; "in 0.14 s" and "(..., 0.31 s)" in messages; the run times of
# the HTML reports), and listed as masked; anything else that differs is listed as DIFFERS.
# Exit 0 when all is identical (modulo the masks), 1 otherwise, 2 on bad usage.
# Usage: scripts/same-outputs.sh [--corpus] [--keep-old] OLD_BIN NEW_BIN [WORKDIR]
#   WORKDIR     default /tmp/same-outputs
#   --corpus    also quality, convert (to .ply), simplify --ratio 0.3, enhance and smooth, each
#               with --json, on every mesh of the shared data's corpus/, cad/ and meshes/*.off
#   --keep-old  reuse WORKDIR/old from an earlier run (same set) instead of running OLD_BIN
#               (OLD_BIN is then ignored; '-' will do)
# The default set: 24 commands on examples/data, tests/data and the shared data, the shared data at
# $MESHPREP_SHARED or else <repo>/../shared/data (commands that need it are skipped, with a message,
# when it is absent). Every command that has --threads gets --threads 1 (deterministic results).
# Inputs are passed as ../in/... (symlinks in WORKDIR), so that the paths the outputs quote do not
# depend on where the repo or WORKDIR is; the inputs' checksums are an output too (inputs.sha256).
# One meshprep process at a time.
set -u
repo=$(cd "$(dirname "$0")/.." && pwd)

usage() { awk '/^# Usage:/ { on = 1 } on && !/^# (Usage|  )/ { exit } on { print substr($0, 3) }' "$0" >&2; exit 2; }
corpus=0 keep_old=0 args=()
for a in "$@"; do
  case $a in
    --corpus) corpus=1 ;;
    --keep-old) keep_old=1 ;;
    -h | --help) usage ;;
    -?*) echo "same-outputs: unknown option $a" >&2; usage ;;
    *) args+=("$a") ;;
  esac
done
[ ${#args[@]} -eq 2 ] || [ ${#args[@]} -eq 3 ] || usage
old_bin=${args[0]} new_bin=${args[1]} work=${args[2]:-/tmp/same-outputs}
abs_bin() {  # BIN: its absolute path, or exit 2 if it is not an executable file
  local b
  b=$(command -v -- "$1" 2>/dev/null)
  if [ -z "$b" ] || [ ! -f "$b" ] || [ ! -x "$b" ]; then echo "same-outputs: not an executable: $1" >&2; exit 2; fi
  echo "$(cd "$(dirname "$b")" && pwd)/$(basename "$b")"
}
new_bin=$(abs_bin "$new_bin") || exit 2
[ $keep_old -eq 1 ] || old_bin=$(abs_bin "$old_bin") || exit 2
set_name=default
[ $corpus -eq 0 ] || set_name=default+corpus
if [ $keep_old -eq 1 ]; then
  # old.info is written last by a complete run: a half-finished WORKDIR/old is not reused
  [ -f "$work/old.info" ] || { echo "same-outputs: --keep-old: no complete earlier run in $work (no old.info)" >&2; exit 2; }
  grep -qxF "set: $set_name" "$work/old.info" || {
    echo "same-outputs: --keep-old: $work/old is of another set ($(sed -n 's/^set: //p' "$work/old.info"), not $set_name)" >&2; exit 2; }
fi
if ! mkdir -p "$work" || ! work=$(cd "$work" && pwd); then echo "same-outputs: cannot create $work" >&2; exit 2; fi

shared=${MESHPREP_SHARED:-$repo/../shared/data}
have_shared=0
[ -d "$shared" ] && have_shared=1
[ $have_shared -eq 1 ] || echo "same-outputs: no shared data at $shared (set MESHPREP_SHARED): its commands are skipped" >&2

# The inputs, seen from WORKDIR/old and WORKDIR/new as ../in/{examples,tests,shared}.
mkdir -p "$work/in"
ln -sfn "$repo/examples/data" "$work/in/examples"
ln -sfn "$repo/tests/data" "$work/in/tests"
if [ $have_shared -eq 1 ]; then ln -sfn "$(cd "$shared" && pwd)" "$work/in/shared"; else rm -f "$work/in/shared"; fi
E=../in/examples T=../in/tests S=../in/shared

# run NAME COMMAND ARGS...: one meshprep command in the current directory (WORKDIR/old or /new).
skipped=() inputs=()
run() {
  local name=$1 a
  shift
  for a in "$@"; do
    case $a in
      $S/*) if [ $have_shared -eq 0 ]; then skipped+=("$name"); return; fi; inputs+=("$a") ;;
      ../in/*) inputs+=("$a") ;;
    esac
  done
  mkdir -p "$(dirname "$name")"
  "$bin" "$@" >"$name.stdout" 2>"$name.stderr"
  echo $? >"$name.rc"
}

# The default set (the prototype's 24 commands), then --corpus's five commands per mesh.
default_set() {
  run q_femur quality $E/femur.off --json q_femur.json --csv q_femur.csv --vtk q_femur.vtk --html q_femur.html --threads 1
  run q_ref quality $S/meshes/decimated/bunny00_0.1_openmesh.off --reference $S/meshes/bunny00.off --samples 20000 --json q_ref.json --threads 1
  run q_table quality $E/fandisk.off --threads 1
  run c_ply convert $E/fandisk.off -o c.ply
  run c_stl convert $E/fandisk.off -o c.stl
  run c_obj convert $T/handle.off -o c.obj
  run r_jack reconstruct $E/jacksboro_10k.xyz -o r_jack.off --json r_jack.json --threads 1
  run r_sph reconstruct $S/points/sphere_20k.xyz -o r_sph.off --json r_sph.json --threads 1
  run s_fan simplify $E/fandisk.off --ratio 0.3 -o s_fan.off --json s_fan.json --threads 1
  run s_bun simplify $S/meshes/bunny00.off --faces 2000 -o s_bun.off --json s_bun.json --threads 1
  run sm_bun smooth $S/meshes/noisy/bunny_noisy.off -o sm_bun.off --json sm_bun.json --threads 1
  run sm_fan smooth $S/meshes/noisy/fandisk_noisy.off -o sm_fan.off --json sm_fan.json --threads 1
  run e_fem enhance $E/femur.off -o e_fem.off --json e_fem.json --threads 1
  run e_cad enhance $T/example004.stl -o e_cad.off --json e_cad.json --threads 1
  run t_fan tetrahedralize $E/fandisk.off -o t_fan.msh --json t_fan.json --threads 1
  run t_fem tetrahedralize $E/femur.off -o t_fem.vtu --json t_fem.json --threads 1
  run i_fan improve t_fan.msh -o i_fan.msh --json i_fan.json --threads 1
  run q_tets quality t_fan.msh --json q_tets.json --threads 1
  run p_fan pipeline $E/fandisk.off --ratio 0.3 -o p_fan --json p_fan.json --quiet --threads 1
  run p_fem pipeline $E/femur.off -o p_fem --json p_fem.json --quiet --threads 1
  run p_jack pipeline $E/jacksboro_10k.xyz -o p_jack --quiet --threads 1
  run p_cad pipeline $S/cad/example001.stl -o p_cad --quiet --threads 1
  run p_cfg pipeline $E/fandisk.off --print-config --threads 1
  run bad_in simplify /nonexistent.off --ratio 0.5 -o x.off --threads 1
}
corpus_meshes() {  # the --corpus inputs, as ../in/shared/...
  local f
  for f in "$shared"/corpus/* "$shared"/cad/* "$shared"/meshes/*.off; do
    case $f in *.off | *.obj | *.ply | *.stl) [ -f "$f" ] && echo "$S/${f#"$shared"/}" ;; esac
  done
}
corpus_set() {
  [ $have_shared -eq 1 ] || { skipped+=("--corpus (all of it)"); return; }
  local m n
  for m in $(corpus_meshes); do
    n=corpus/${m#"$S"/}; n=${n%.*}  # ../in/shared/cad/CSG.stl -> corpus/cad/CSG.*
    run "$n.quality" quality "$m" --json "$n.quality.json" --threads 1
    run "$n.convert" convert "$m" -o "$n.convert.ply" --json "$n.convert.json"
    run "$n.simplify" simplify "$m" --ratio 0.3 -o "$n.simplify.off" --json "$n.simplify.json" --threads 1
    run "$n.enhance" enhance "$m" -o "$n.enhance.off" --json "$n.enhance.json" --threads 1
    run "$n.smooth" smooth "$m" -o "$n.smooth.off" --json "$n.smooth.json" --threads 1
  done
}

# side old|new BIN: the whole set into WORKDIR/SIDE; SIDE.info (set, binary, date) marks it complete.
side() {
  local dir=$work/$1 start=$SECONDS
  bin=$2 skipped=() inputs=()
  rm -rf "$dir" "$work/$1.info" && mkdir -p "$dir" && cd "$dir" || exit 2
  echo "same-outputs: running $set_name with $bin into $dir"
  default_set
  [ $corpus -eq 0 ] || corpus_set
  # the inputs' checksums, so that changed input data shows up as such
  printf '%s\n' "${inputs[@]}" | sort -u | while read -r f; do
    [ -z "$f" ] || sha256sum "$f" 2>/dev/null || echo "missing  $f"
  done > inputs.sha256
  [ ${#skipped[@]} -eq 0 ] || echo "same-outputs: skipped (no shared data): ${skipped[*]}" >&2
  printf 'set: %s\nbinary: %s\ndate: %s\n' "$set_name" "$bin" "$(date -u '+%F %T UTC')" > "$work/$1.info"
  echo "same-outputs: $1 took $((SECONDS - start)) s"
}

# mask FILE: FILE with its wall-clock figures replaced by T.
mask() {
  case $1 in
    *.html)  # one tag a line; "took 0.02 s", "1.7 s in all", cells "0.05 s" and the "time (s)" column
      sed -E 's/</\n</g' "$1" | sed -E 's/took [0-9.]+ s/took T s/; s/[0-9.]+ s in all/T s in all/; s/^(<td>)[0-9.]+ s$/\1T s/' |
        awk '/^<table[ >]/ { timecol = 0 }
             /^<tr[ >]/ { col = 0 }
             /^<th[ >]/ { col++; if ($0 ~ />time \(s\)$/) timecol = col }
             /^<td[ >]/ { col++; if (timecol && col == timecol) sub(/>[0-9][-0-9.e+]*$/, ">T") }
             { print }' ;;
    *) sed -E 's/"(seconds|time_seconds|tetgen_seconds)": *-?[0-9][-0-9.e+]*/"\1": T/g;
              s/ in [0-9][0-9.e+-]* s\b/ in T s/g; s/, [0-9][0-9.e+-]* s\)/, T s)/g' "$1" ;;
  esac
}

total=$SECONDS
if [ $keep_old -eq 1 ]; then
  echo "same-outputs: reusing $work/old ($(sed -n 's/^binary: //p' "$work/old.info"), $(sed -n 's/^date: //p' "$work/old.info"))"
else
  side old "$old_bin"
fi
side new "$new_bin"

cd "$work" || exit 2
bad=0 same=0 masked=0
while IFS= read -r f; do
  if [ ! -e "new/$f" ]; then echo "missing in new: $f"; bad=1
  elif cmp -s "old/$f" "new/$f"; then same=$((same + 1))
  elif cmp -s <(mask "old/$f") <(mask "new/$f"); then echo "masked: $f"; masked=$((masked + 1))
  else echo "DIFFERS: $f"; bad=1
  fi
done < <(cd old && find . -type f | sed 's|^\./||' | sort)
while IFS= read -r f; do
  [ -e "old/$f" ] || { echo "missing in old: $f"; bad=1; }
done < <(cd new && find . -type f | sed 's|^\./||' | sort)
echo "same-outputs: $same identical, $masked identical after masking wall-clock figures ($((SECONDS - total)) s in all)"
if [ $bad -eq 0 ]; then echo "same-outputs: SAME outputs"; else echo "same-outputs: outputs DIFFER (diff $work/old/FILE $work/new/FILE)"; fi
exit $bad
