#!/usr/bin/env bash
# A fresh user's path (README "Running a case"): 'source etc/bashrc' puts the applications on PATH
# (impactSph -listModels works from any directory) and a tutorial copied outside the tree runs its
# own Allrun there, finding bin/tools/RunFunctions through MFDYN_DIR. Without etc/bashrc, the
# copy's Allrun must stop with a message that says what to do, not a bash error.
# $1 = build directory, $2 = this source directory.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
ROOT="$(cd "$SOURCE/../../.." && pwd)"
export OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-copied.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
case "$WORK/" in "$ROOT/"*) fail "the work directory $WORK is inside the tree $ROOT: the test proves nothing" ;; esac
# A clean environment: no build directory on PATH, no MFDYN_* variables from the caller.
clean=(env -u MFDYN_DIR -u MFDYN_ROOT -u MFDYN_BUILD PATH=/usr/local/bin:/usr/bin:/bin HOME="$WORK")

cp -r "$ROOT/tutorials/impactSph/sodShockTube" "$WORK/sod"
(cd "$WORK/sod" && rm -rf 0 [1-9]* log.* postProcessing particles.pvd gamma5over3 ./*.png)
# Short: a tenth of the run, the gamma = 5/3 copy made by Allrun from this controlDict too.
"$BUILD/bin/mfDictionary" "$WORK/sod/system/controlDict" -entry endTime -set 0.02 > /dev/null
"$BUILD/bin/mfDictionary" "$WORK/sod/system/controlDict" -entry writeInterval -set 0.01 > /dev/null

# 1. Without etc/bashrc the copy cannot find RunFunctions: exit 1 and a message naming etc/bashrc.
set +e
out=$(cd "$WORK/sod" && "${clean[@]}" bash ./Allrun 2>&1)
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "Allrun of a copy without etc/bashrc exited $rc (expected 1): $out"
grep -q "cannot find bin/tools/RunFunctions: source <mfdyn>/etc/bashrc" <<< "$out" ||
    fail "Allrun of a copy without etc/bashrc did not say what to do: $out"
[ ! -e "$WORK/sod/log.particleGen" ] || fail "Allrun ran something though it could not find RunFunctions"

# 2. With etc/bashrc (MFDYN_BUILD names this build, as a user with another build directory would).
cat > "$WORK/user.sh" <<SCRIPT
set -e
MFDYN_BUILD="$BUILD" source "$ROOT/etc/bashrc"
[ "\$MFDYN_DIR" = "$(cd "$ROOT" && pwd -P)" ] || { echo "MFDYN_DIR is '\$MFDYN_DIR'"; exit 1; }
cd "$WORK"
impactSph -listModels > listModels.txt
cd "$WORK/sod"
./Allrun
SCRIPT
"${clean[@]}" bash "$WORK/user.sh" > "$WORK/log.user" 2>&1 || fail "the user's script failed: $(tail -n 20 "$WORK/log.user")"
grep -q "^equationOfState" "$WORK/listModels.txt" && grep -q "idealGas" "$WORK/listModels.txt" ||
    fail "impactSph -listModels did not list equationOfState/idealGas: $(head "$WORK/listModels.txt")"
for log in "$WORK/sod/log.impactSph" "$WORK/sod/gamma5over3/log.impactSph"; do
    [ -f "$log" ] || fail "Allrun did not run impactSph ($log missing): $(tail "$WORK/log.user")"
    grep -q "^End$" "$log" || fail "$log does not end the run: $(tail "$log")"
done
[ -f "$WORK/sod/0.02/particles.vtp" ] || fail "no 0.02/particles.vtp in the copy"
echo "PASS: etc/bashrc puts impactSph on PATH, and a copy of sodShockTube in $WORK runs its Allrun"
