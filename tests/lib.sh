# lib.sh: sourced by every tests/*.test script.
# The harness sets ECLAT (the binary), top_srcdir and OIIOTOOL.
set -u
: "${ECLAT:?run the tests through make check}"
: "${top_srcdir:?run the tests through make check}"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/eclat-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
# A tests/*.tap script reports each case as a TAP line, so that make check
# counts (and names) each case; a tests/*.test script reports one result.
cases=0
case $0 in *.tap) tap=1 ;; *) tap= ;; esac

fail() {
	cases=$((cases + 1))
	if [ -n "$tap" ]; then echo "not ok $cases - $*"; else echo "FAIL: $*"; fi
	failures=$((failures + 1))
}

pass() {
	cases=$((cases + 1))
	if [ -n "$tap" ]; then echo "ok $cases - $*"; else echo "ok: $*"; fi
}

# finish: the script's exit status, 1 when any check failed. Cases left out for
# want of an optional mesh are named on one line that make check gathers.
finish() {
	[ -z "$left_out" ] || echo "left out: $(basename "$0" .test) ($left_out)"
	[ -z "$tap" ] || { echo "1..$cases"; exit 0; }   # the failures are in the TAP lines
	[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
	exit 0
}

# test_program NAME ARGS...: runs tests/NAME, one of the C test programs. In the
# sanitizer build it runs through LSAN_RUN, as eclat does (lsan-run.sh says why).
test_program() {
	prog="${top_builddir:?run the tests through make check}/tests/$1"
	shift
	${LSAN_RUN:+"$LSAN_RUN"} "$prog" "$@"
}

# ---- meshes (issue 13): make check needs nothing from outside the repository
# but what ./bootstrap installs. The tests' meshes:
#   - the blob, written by tests/gen_mesh (81,280 triangles): the large mesh;
#   - Wuson, a real model (3,732 triangles) of assimp's test models (Debian's
#     assimp-testmodels, TEST_MODELS), in PLY, OBJ, STL and OFF;
#   - optionally, the team's larger meshes in MESH_DIR (configure
#     --with-mesh-dir): a case on one of them runs when it is there, and is
#     named by finish when it is not (optional_mesh).
BLOB_TRIANGLES=81280
WUSON_TRIANGLES=3732
TEST_MODELS=${TEST_MODELS:-/usr/share/assimp/models}
WUSON_PLY=$TEST_MODELS/PLY/Wuson.ply
WUSON_OBJ=$TEST_MODELS/OBJ/WusonOBJ.obj
WUSON_STL=$TEST_MODELS/STL/Wuson.stl
WUSON_OFF=$TEST_MODELS/OFF/Wuson.off
left_out=

# blob FILE...: writes the blob to each FILE (.obj, .ply or .stl).
blob() {
	"${top_builddir:?run the tests through make check}/tests/gen_mesh" "$@" > /dev/null ||
		{ fail "tests/gen_mesh $*"; finish; }
}

# need_test_models: ends the test, failed, when assimp's test models are missing.
need_test_models() {
	for f in "$WUSON_PLY" "$WUSON_OBJ" "$WUSON_STL" "$WUSON_OFF"; do
		[ -f "$f" ] || { fail "no $f: apt-get install assimp-testmodels (./bootstrap does)"; finish; }
	done
}

# optional_mesh NAME: true when MESH_DIR holds NAME; else the case is left out.
optional_mesh() {
	[ -f "${MESH_DIR:-}/$1" ] && return 0
	left_out="${left_out:+$left_out }$1"
	return 1
}

# region_mean IMAGE GEOMETRY: the mean R G B of a region (WxH+X+Y) of IMAGE,
# as computed by oiiotool (openimageio-tools).
region_mean() {
	"${OIIOTOOL:-oiiotool}" "$1" --cut "$2" --printstats 2>&1 |
		awk '/Stats Avg:/ { print $3, $4, $5; found = 1 } END { if (!found) exit 1 }'
}

# near "A B C" "X Y Z" TOL: every |A - X| <= TOL * max(|X|, 0.01).
near() {
	echo "$1 $2 $3" | awk '{
		ok = 1
		for (i = 1; i <= 3; i++) {
			want = $(i + 3); got = $i; scale = want < 0 ? -want : want
			if (scale < 0.01) scale = 0.01
			d = got - want; if (d < 0) d = -d
			if (d > $7 * scale) ok = 0
		}
		exit ok ? 0 : 1 }'
}
