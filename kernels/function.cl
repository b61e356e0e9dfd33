/* function.cl: the scene's POV-Ray functions. lower_function.c writes them as
 * OpenCL C after the kernels' files when the scene has any (and builds with
 * SCENE_FUNCTIONS); this declares what they define, so that patterns can call
 * them, and defines it when there are none. */

/* Function f of the scene (scene.functions) at p: x, y and z are p's. */
float scene_function_pattern(int f, float3 p);

#ifndef SCENE_FUNCTIONS
float scene_function_pattern(int f, float3 p)
{
	return 0.0f;
}
#endif
