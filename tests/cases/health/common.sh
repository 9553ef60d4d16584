# Shared by the health case scripts: $1 = build directory, $2 = source root.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
export MFDYN_LIBRARY_PATH="$BUILD/testLibraries"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-health.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

. "$(dirname "${BASH_SOURCE[0]}")/faults.sh"
