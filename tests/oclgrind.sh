#!/bin/sh
# make check-oclgrind (issue 20; not in make check): a tiny render with each
# integrator on oclgrind's simulated OpenCL device, which reports a kernel's
# reads and writes outside its buffers and misuses of the API (not its
# --uninitialized check: oclgrind 21.10 stops at LLVM's freeze instruction,
# which its compiler makes of our kernels). The scene touches what the kernels read from
# the most buffers: an image map, an isosurface's function, CSG, text, a
# pattern, a torus. Any report fails it.
. "$top_srcdir/tests/lib.sh"
command -v oclgrind > /dev/null 2>&1 || { fail "oclgrind is missing: apt-get install oclgrind"; finish; }
cd "$tmp" || exit 1
"${OIIOTOOL:-oiiotool}" --create 4x4 3 --fill:color=0.2,0.8,0.3 4x4 -o tex.png > /dev/null 2>&1 ||
	fail "oiiotool cannot write a PNG"
cat > scene.scn <<'SCENE'
camera { location <0, 1, -5> look_at 0 }
light_source { <0, 5, -5> color 1 }
sphere { <-1.5, 0, 0>, 0.7 pigment { image_map { png "tex.png" } } }
isosurface { function { x * x + y * y + z * z - 0.5 } contained_by { box { -1, 1 } } pigment { rgb 1 }
             translate <1.5, 0, 0> }
difference { box { -0.5, 0.5 } sphere { 0, 0.6 } pigment { rgb <1, 0, 0> } translate <0, 1, 0> }
text { ttf "timrom.ttf" "Hi" 0.2, 0 pigment { rgb 1 } translate <-0.5, -1, -1> }
plane { y, -1 pigment { checker rgb 1, rgb 0 } }
torus { 0.5, 0.1 pigment { granite } translate <0, 0, 1> }
SCENE
for integrator in whitted path; do
	timeout 900 oclgrind --check-api -q "$ECLAT" -q --integrator "$integrator" -W 8 -H 6 -s 2 \
		-o "$integrator.png" scene.scn > "$integrator.out" 2>&1
	status=$?
	# PoCL's and oclgrind's compilers both say "N warning(s) generated"; the rest is a report
	grep -vE '^[0-9]+ warnings? generated\.$' "$integrator.out" > "$integrator.report"
	if [ "$status" -ne 0 ] || [ -s "$integrator.report" ]; then
		fail "$integrator on oclgrind: exit status $status"
		head -n 40 "$integrator.report"
	else
		pass "$integrator on oclgrind: no report"
	fi
done
finish
