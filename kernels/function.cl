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
