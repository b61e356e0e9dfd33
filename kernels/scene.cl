/* scene.cl: the scene's buffers as one value that the functions of the
 * integrators take (Cycles' KernelGlobals), made from the one list in shared.h
 * (SCENE_BUFFERS), as are the render kernels' parameters:
 *
 *   kernel void render_x(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, ...)
 *   scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
 */

struct scene_data {   /* the typedef: function.cl, whose functions take it */
#define SCENE_MEMBER(TYPE, NAME) global const TYPE *NAME;
	SCENE_BUFFERS(SCENE_MEMBER)
#undef SCENE_MEMBER
	global const dev_params *p;
	uint *counts;        /* the work item's ray and test counters (COUNT_) */
};

#define SCENE_PARAM(TYPE, NAME) global const TYPE *NAME,
#define SCENE_FIELD(TYPE, NAME) NAME,
