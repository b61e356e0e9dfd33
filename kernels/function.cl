/* function.cl: the scene's POV-Ray functions. lower_function.c writes them as
 * OpenCL C after the kernels' files when the scene has any (and builds with
 * SCENE_FUNCTIONS); this declares what they define, so that patterns and
 * shapes can call them, and defines it when there are none.
 *
 * A function that calls a pattern or pigment function reads the scene's
 * pattern buffers (function_pattern.cl), so the functions take the scene's
 * buffers, defined later (scene.cl): patterns pass theirs, and so does the
 * traversal to an isosurface (PRIM_SHAPES' S row); raycast.cl's test kernels
 * have none and pass 0, which the pattern calls check. */

typedef struct scene_data scene_data;

/* Function f of the scene (scene.functions) at (x, y, z), its first three
 * parameters (the others 0), in double where the device has it. */
static real scene_function_at(const scene_data *sc, int f, real x, real y, real z);

#ifndef SCENE_FUNCTIONS
static real scene_function_at(const scene_data *sc, int f, real x, real y, real z)
{
	return (real)0;
}
#endif

/* As a pattern sees it: at a point of the pattern's space. */
static inline float scene_function_pattern(const scene_data *sc, int f, float3 p)
{
	return (float)scene_function_at(sc, f, (real)p.x, (real)p.y, (real)p.z);
}

/* POV-Ray's f_polytubes (FOP_POLYTUBES): x y z, the number of tubes (at most
 * 256, none for NaN), and the coefficients of their distance from the y axis,
 * a polynomial of y; as scene_function.c's polytubes. */
static real function_polytubes(real x, real y, real z, real tubes, real p1, real p2, real p3, real p4, real p5)
{
	real y2 = y * y, radius = p1 + p2 * y + p3 * y2 + p4 * y2 * y + p5 * y2 * y2;
	int n = tubes > 0 ? (int)fmin(tubes, (real)256) : 0;
	real r = -10000;
	for (int i = 0; i < n; i++) {
		real dx = x - radius * sin((real)6.283185307179586 / tubes * i),
		     dz = z - radius * cos((real)6.283185307179586 / tubes * i);
		r = fmax(r, -sqrt(dx * dx + dz * dz));
	}
	return -r;
}
