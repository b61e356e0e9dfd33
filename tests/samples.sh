#!/bin/sh
# samples.sh: POV-Ray's own sample scenes rendered by povray and by eclat's
# Whitted integrator, and how many of eclat's images match POV-Ray's: what a
# POV-Ray user sees, measured. Not part of make check (it takes a while).
#
#   tests/samples.sh [-j JOBS] [-e ECLAT] [-t SECONDS] OUTDIR [SCENE...]
#
# Each scene renders at 160x120, one ray a pixel (povray -A), POV-Ray's images
# kept in OUTDIR/pov (made once, reused by later runs), eclat's in
# OUTDIR/eclat. A scene POV-Ray cannot render in the time limit is left out.
# An eclat image "matches" when 99% of its pixels are within 3/255 of
# POV-Ray's, and "comes close" when 90% are within 16/255. OUTDIR/results.tsv
# has a line a scene: the scene, match / close / differs / failed, and the
# share of pixels within 3/255; the last lines printed are the counts.
set -u
jobs=2 eclat=${ECLAT:-./eclat} limit=60
while getopts j:e:t: opt; do
	case $opt in
	j) jobs=$OPTARG ;;
	e) eclat=$OPTARG ;;
	t) limit=$OPTARG ;;
	*) echo "usage: $0 [-j JOBS] [-e ECLAT] [-t SECONDS] OUTDIR [SCENE...]" >&2; exit 2 ;;
	esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { echo "usage: $0 [-j JOBS] [-e ECLAT] [-t SECONDS] OUTDIR [SCENE...]" >&2; exit 2; }
out=$1; shift
examples=${POVRAY_EXAMPLES:-/usr/share/doc/povray/examples}
include=${POV_INCLUDE:-/usr/share/povray-3.7/include}
eclat=$(cd "$(dirname "$eclat")" && pwd)/$(basename "$eclat")
mkdir -p "$out/pov" "$out/eclat" || exit 1
out=$(cd "$out" && pwd)
: > "$out/empty.ini"

if [ $# -eq 0 ]; then
	find "$examples" -name '*.pov' | sort > "$out/scenes"
else
	printf '%s\n' "$@" > "$out/scenes"
fi

# One scene: both renders (POV-Ray's only when missing), then the comparison.
cat > "$out/one.sh" <<EOF
scene=\$1
name=\$(printf '%s' "\${scene#$examples/}" | tr '/' '_' | sed 's/\.pov\$//')
dir=\$(dirname "\$scene")
pov=$out/pov/\$name.png ecl=$out/eclat/\$name.png
run=\$(mktemp -d "$out/run.XXXXXX")
cd "\$run" || exit 1
if [ ! -e "\$pov" ] && [ ! -e "\$pov.failed" ]; then
	POVINI=$out/empty.ini timeout $limit povray "+I\$scene" "+O\$pov" +W160 +H120 -A -D -V -P -GA +FN +WT1 \\
		"+L\$dir" "+L$include" > /dev/null 2>&1 || { rm -f "\$pov"; : > "\$pov.failed"; }
fi
result=failed share=0
if [ -e "\$pov" ]; then
	rm -f "\$ecl"
	timeout $limit "$eclat" -q --integrator whitted --skip-unsupported -W 160 -H 120 -I "\$dir" "\$scene" \\
		-o "\$ecl" > /dev/null 2>&1
	if [ -s "\$ecl" ]; then
		# idiff's status: 0 pass, 1 warn (still within the limits), 2 and over fail
		idiff -fail 0.0118 -failpercent 1 "\$pov" "\$ecl" > /dev/null 2>&1
		if [ \$? -le 1 ]; then result=match
		else
			idiff -fail 0.0628 -failpercent 10 "\$pov" "\$ecl" > /dev/null 2>&1
			if [ \$? -le 1 ]; then result=close; else result=differs; fi
		fi
		over=\$(idiff -fail 0.0118 "\$pov" "\$ecl" 2>&1 | sed -n 's/.*(\([0-9.]*\)%) over 0.0118/\1/p')
		share=\$(awk -v o="\${over:-0}" 'BEGIN { printf "%.1f", 100 - o }')
	fi
	printf '%s\t%s\t%s\n' "\${scene#$examples/}" "\$result" "\$share"
fi
cd / && rm -rf "\$run"
EOF
xargs -P "$jobs" -n 1 sh "$out/one.sh" < "$out/scenes" | sort > "$out/results.tsv"
total=$(wc -l < "$out/results.tsv")
for r in match close differs failed; do
	printf '%s\t%d\n' "$r" "$(awk -F '\t' -v r="$r" '$2 == r' "$out/results.tsv" | wc -l)"
done
echo "of $total scenes POV-Ray rendered (results in $out/results.tsv)"
