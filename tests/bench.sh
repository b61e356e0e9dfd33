#!/bin/sh
# make bench: the paper's statue scene (the Cornell box holding the Stanford bunny,
# 1080x1080, 5 bounces), a CSG-heavy scene (tests/bench/csg_blocks.scn) and a
# spotlight's beam through media onto the bunny (tests/bench/media_beam.scn)
# rendered on the OpenCL device, with paths per second and
# rays per second by kind, and the BVH's tests per path with the SAH builder and
# with the paper's median split. Figures are ratios within one run: the machine
# is shared and noisy.
# With Embree (EMBREE_BENCH: tests/bench/embree_bench, which make bench builds
# when configure found it), first the comparison with it, each pair of runs
# interleaved round by round (ROUNDS, 5): rays per second through the BVH
# (camera, diffuse and shadow rays, eclat's traversal-only kernel against
# rtcIntersect1/rtcOccluded1 on 2 threads), paths per second of the render
# against a minimal Embree path tracer, and BVH build times.
# With POV-Ray, --integrator whitted against povray +WT2 on the bunny and the
# dragon (tests/bench/whitted_mesh.scn), wall times interleaved the same way.
set -u
: "${ECLAT:?}" "${top_srcdir:?}" "${MESH_DIR:?}"
EMBREE_BENCH=${EMBREE_BENCH:-}
ROUNDS=${ROUNDS:-5}

# The figures are on the team's larger meshes, which the repository does not
# hold (README.md, Tests). Without them there is nothing to measure: say where
# they come from and exit 1, so that no one takes an empty run for a benchmark.
missing=
for f in bunny.ply dragon.obj igea.ply; do
	[ -f "$MESH_DIR/$f" ] || missing="$missing $f"
done
if [ -n "$missing" ]; then
	cat >&2 <<EOF
make bench: the folder of the larger test meshes, $MESH_DIR,
lacks$missing. make bench renders and builds on three meshes:
  bunny.ply   the Stanford Bunny, bun_zipper.ply of bunny.tar.gz (69,451 triangles)
  dragon.obj  the Stanford Dragon decimated to 100,000 triangles, as OBJ
  igea.ply    the Igea head (Cyberware), 268,686 triangles
The bunny and the dragon come from the Stanford 3D Scanning Repository,
http://graphics.stanford.edu/data/3Dscanrep/ (decimate the dragon, dragon_vrip.ply,
with e.g. MeshLab); Igea from github.com/alecjacobson/common-3d-test-models
(data/igea.ply). Put them in a folder and run ./configure --with-mesh-dir=DIR,
or in shared/data/meshes beside the repository, configure's default.
EOF
	exit 1
fi
SAMPLES=${SAMPLES:-4}
scene=$top_srcdir/tests/bench/cornell_bunny.scn
mesh=$MESH_DIR/bunny.ply
out=$(mktemp -d "${TMPDIR:-/tmp}/eclat-bench.XXXXXX")
trap 'rm -rf "$out"' EXIT

run() { # run LABEL OPTIONS...: prints eclat's summary and statistics
	label=$1; shift
	echo "== $label"
	"$ECLAT" --stats -W 1080 -H 1080 --max-depth 5 -D Mesh="\"$mesh\"" --io-allow "$MESH_DIR" -o "$out/bench.exr" \
		"$@" "$scene" \
		2> "$out/log" || { cat "$out/log"; exit 1; }
	grep -v '^\r' "$out/log" | tr '\r' '\n' | grep -E '^(eclat|bvh|rays):' | sed 's/^/  /'
}

camera_tests() { # node + primitive tests per camera ray, from --stats
	sed -n 's/^rays: camera: .* \([0-9.]*\) node tests and \([0-9.]*\) primitive tests.*/\1 \2/p' "$out/log" |
		awk '{ print $1 + $2 }'
}
# A build takes tens of milliseconds, which one busy moment of this shared
# machine can double: each mesh is built BUILDS times, best and median shown.
BUILDS=${BUILDS:-7}
build_ms() { # build_ms MESH: best and median milliseconds to build its BVH
	printf '#declare M = mesh { file "%s" }\nobject { M }\n' "$1" > "$out/build.scn"
	i=0
	while [ "$i" -lt "$BUILDS" ]; do
		"$ECLAT" --check --stats --io-allow "$MESH_DIR" "$out/build.scn" 2>&1 | sed -n 's/^bvh: mesh .* built in \([0-9.]*\) ms.*/\1/p'
		i=$((i + 1))
	done | sort -n | awk '{ t[NR] = $1 } END { print t[1], t[int((NR + 1) / 2)] }'
}

paths_of() { sed -n 's/.*: \([0-9.]*\) M paths\/s.*/\1/p' "$out/log" | tail -n 1; }

best_median() { # best_median: the highest and the median of the numbers on stdin
	sort -g | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print v[NR], m }'
}

if [ -n "$EMBREE_BENCH" ]; then
	echo "== against Embree, $ROUNDS rounds, each eclat then Embree (ratios: medians of the same run)"
	"$EMBREE_BENCH" rays "$scene" "$mesh" "$ROUNDS" | sed 's/^/  /' || exit 1
	r=0
	: > "$out/eclat_paths"
	: > "$out/embree_paths"
	while [ "$r" -lt "$ROUNDS" ]; do
		"$ECLAT" --stats -W 1080 -H 1080 --max-depth 5 -s "$SAMPLES" -D Mesh="\"$mesh\"" --io-allow "$MESH_DIR" \
			-o "$out/bench.exr" "$scene" 2> "$out/log" || { cat "$out/log"; exit 1; }
		e=$(paths_of)
		b=$("$EMBREE_BENCH" paths "$scene" "$mesh" 1080 1080 "$SAMPLES" 5 | sed -n 's/^embree paths: \([0-9.]*\).*/\1/p')
		echo "$e" >> "$out/eclat_paths"
		echo "$b" >> "$out/embree_paths"
		r=$((r + 1))
		echo "  round $r: paths, 1080x1080, $SAMPLES samples, 5 bounces: eclat $e M paths/s, Embree $b"
	done
	set -- $(best_median < "$out/eclat_paths") $(best_median < "$out/embree_paths")
	echo "$@" | awk '{ printf "  summary: paths, M paths/s best and median: eclat %.2f %.2f, Embree (minimal path tracer) %.2f %.2f: eclat/Embree %.2fx\n", $1, $2, $3, $4, $2 / $4 }'
	"$EMBREE_BENCH" build "$BUILDS" "$MESH_DIR/bunny.ply" "$MESH_DIR/igea.ply" | sed 's/^/  /' || exit 1
else
	echo "== against Embree: left out, configure found no Embree 3 (apt-get install libembree-dev; ./bootstrap installs it)"
fi

# --integrator whitted against POV-Ray with 2 threads (+WT2) on the bunny and the
# dragon, 1280x960, wall time of the whole command (start-up, parsing the mesh2
# and writing the PNG included), the two programs interleaved round by round on
# the same scene file and the same mesh2 include (eclat --export-mesh2).
whitted_ratio=
if command -v povray > /dev/null 2>&1; then
	echo "== --integrator whitted against povray +WT2, 1280x960, $ROUNDS rounds (wall time, start-up included)"
	cp "$top_srcdir/tests/bench/whitted_mesh.scn" "$out/whitted.pov"
	: > "$out/empty.ini"
	wall_s() { # wall_s COMMAND...: the seconds it took, or nothing when it failed
		t0=$(date +%s.%N)
		"$@" > "$out/whitted.log" 2>&1 || { sed 's/^/    /' "$out/whitted.log" | tail -n 5 >&2; return 1; }
		echo "$t0 $(date +%s.%N)" | awk '{ printf "%.3f\n", $2 - $1 }'
	}
	for m in bunny.ply dragon.obj; do
		name=${m%.*}
		"$ECLAT" --export-mesh2 "$MESH_DIR/$m" -o "$out/${name}_mesh2.inc" || exit 1
		decl=$(sed -n 's/^#declare \([A-Za-z_0-9]*\) = mesh2.*/\1/p' "$out/${name}_mesh2.inc")
		printf '#include "%s_mesh2.inc"\n#declare Mesh = %s;\n' "$name" "$decl" > "$out/mesh.inc"
		: > "$out/eclat_s"
		: > "$out/povray_s"
		r=0
		while [ "$r" -lt "$ROUNDS" ]; do
			e=$(cd "$out" && wall_s "$ECLAT" -q --integrator whitted -W 1280 -H 960 whitted.pov -o whitted.png) || exit 1
			p=$(cd "$out" && POVINI="$out/empty.ini" wall_s povray +Iwhitted.pov +Owhitted_pov.png +W1280 +H960 +WT2 -D -V -P +FN) ||
				exit 1
			echo "$e" >> "$out/eclat_s"
			echo "$p" >> "$out/povray_s"
			r=$((r + 1))
			echo "  round $r: $name, eclat $e s, povray $p s"
		done
		# best_median gives the highest and the median: of the negated times, the fastest
		set -- $(sed 's/^/-/' "$out/eclat_s" | best_median) $(sed 's/^/-/' "$out/povray_s" | best_median)
		echo "$@" | awk -v name="$name" '{ printf "  summary: %s, s best and median: eclat %.2f %.2f, povray +WT2 %.2f %.2f: povray/eclat %.2fx (target 3x)\n", name, -$1, -$2, -$3, -$4, $4 / $2 }'
		whitted_ratio="$whitted_ratio $name $(echo "$@" | awk '{ printf "%.2fx", $4 / $2 }')"
	done
else
	echo "== --integrator whitted against POV-Ray: left out, no povray on the PATH (./bootstrap installs it)"
fi

run "path tracer, SAH BVH, binary layout, $SAMPLES samples" -s "$SAMPLES" --bvh-layout binary
paths_binary=$(paths_of)
sah=$(sed -n 's/^rays: all: .*, \([0-9.]*\) tests per path.*/\1/p' "$out/log")
sah_camera=$(camera_tests)
run "path tracer, SAH BVH, wide layout (the default), $SAMPLES samples" -s "$SAMPLES" --bvh-layout wide
paths=$(paths_of)
wide_camera=$(camera_tests)
run "the paper's random walk, SAH BVH, $SAMPLES samples" -s "$SAMPLES" --integrator naive
run "path tracer, the paper's median-split BVH, 1 sample" -s 1 --bvh median --bvh-layout binary
median=$(sed -n 's/^rays: all: .*, \([0-9.]*\) tests per path.*/\1/p' "$out/log")
median_camera=$(camera_tests)
bunny_ms=$(build_ms "$MESH_DIR/bunny.ply")
igea_ms=$(build_ms "$MESH_DIR/igea.ply")

echo "== CSG: 1,000 blocks, each a box less three cylinders, 1080x1080, $SAMPLES samples"
"$ECLAT" --stats -W 1080 -H 1080 --max-depth 5 -s "$SAMPLES" -o "$out/csg.exr" "$top_srcdir/tests/bench/csg_blocks.scn" \
	2> "$out/log" || { cat "$out/log"; exit 1; }
tr '\r' '\n' < "$out/log" | grep -E '^(eclat|bvh|rays):' | sed 's/^/  /'
csg_paths=$(paths_of)

echo "== media: a spotlight's beam through scattering air onto the bunny, 1080x1080, $SAMPLES samples"
"$ECLAT" --stats -W 1080 -H 1080 -s "$SAMPLES" -D Mesh="\"$mesh\"" --io-allow "$MESH_DIR" -o "$out/media.exr" \
	"$top_srcdir/tests/bench/media_beam.scn" 2> "$out/log" || { cat "$out/log"; exit 1; }
tr '\r' '\n' < "$out/log" | grep -E '^(eclat|bvh|rays):' | sed 's/^/  /'
media_paths=$(paths_of)

echo "== 10,000 dragons (a billion triangles), 480x270, 4 samples"
"$ECLAT" --stats -W 480 -H 270 -s 4 -D Mesh="\"$MESH_DIR/dragon.obj\"" --io-allow "$MESH_DIR" -o "$out/dragons.png" \
	"$top_srcdir/tests/bench/dragons.scn" 2> "$out/log" || { cat "$out/log"; exit 1; }
tr '\r' '\n' < "$out/log" | grep -E '^(eclat|bvh):' | sed 's/^/  /'

echo "== summary"
echo "$paths $sah $median $sah_camera $median_camera $paths_binary $wide_camera $bunny_ms $igea_ms $BUILDS $csg_paths $media_paths" | awk '{
	printf "  path tracer: %.2f M paths/s\n", $1
	printf "  CSG blocks (1,000 boxes less three cylinders each): %.2f M paths/s, %.2fx the Cornell box'\''s\n", $13, ($1 > 0 ? $13 / $1 : 0)
	printf "  media (a spotlight beam through scattering air, the bunny): %.2f M paths/s, %.2fx the Cornell box'\''s\n", $14, ($1 > 0 ? $14 / $1 : 0)
	printf "  BVH layouts: wide %.2f M paths/s, binary %.2f (wide/binary %.2fx); tests per camera ray,\n", $1, $6, ($6 > 0 ? $1 / $6 : 0)
	printf "  counting each child box: wide %.1f, binary %.1f\n", $7, $4
	printf "  BVH tests per camera ray (binary layout): SAH %.1f (target 24 or fewer), median split %.1f (the paper: about 108);\n", $4, $5
	printf "  per path (all rays of a pixel sample): SAH %.1f, median split %.1f\n", $2, $3
	printf "  SAH build, best and median of %d: bunny (69,451 triangles) %.1f and %.1f ms (target 20),\n", $12, $8, $9
	printf "  igea (268,686) %.1f and %.1f ms (target 80)\n", $10, $11 }'
[ -z "$whitted_ratio" ] || echo "  --integrator whitted, faster than povray +WT2 by (medians, 1280x960, target 3x):$whitted_ratio"
