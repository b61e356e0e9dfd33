# lib.sh: sourced by every tests/*.test script.
# The harness sets ECLAT (the binary), top_srcdir and OIIOTOOL.
set -u
: "${ECLAT:?run the tests through make check}"
: "${top_srcdir:?run the tests through make check}"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/eclat-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0

fail() {
	echo "FAIL: $*"
	failures=$((failures + 1))
}

pass() {
	echo "ok: $*"
}

# finish: the script's exit status, 1 when any check failed.
finish() {
	[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
	exit 0
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
