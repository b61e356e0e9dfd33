/* function_pattern.cl: the pattern and pigment functions that the scene's
 * generated functions call (FOP_PATTERN, FOP_PIGMENT: POV-Ray's f_pattern and
 * f_pigment), on the pattern trees lowering made for them (with no
 * transformation around them: a function's x, y, z are the pattern's space
 * before its own transformations).
 *
 * OpenCL C has no recursion, so the call graph must stay acyclic: a pattern
 * reaches a function (pattern_at, PATTERN_FUNCTION), the function reaches
 * these, and these reach only pattern_plain and function_pigment_tree, which
 * run no function pattern. Evaluation refuses the pattern trees that would
 * need one (eval_function.c). */

/* What aoi and slope see here: POV-Ray gives the function no surface. */
#define FUNCTION_NO_NORMAL ((float3)(0.0f, 0.0f, 1.0f))

static inline float function_pattern_value(const scene_data *sc, global const dev_pattern *pt, float3 q, float3 n, float3 d)
{
	return pattern_plain(pt, sc->warps, pattern_warp_point(pt, sc->warps, q), n, d);
}

TEXTURE_PIGMENT_TREE(function_pigment_tree, function_pattern_value)

/* A pattern function's value at p: its pattern's, through its warps. */
static real function_pattern(const scene_data *sc, int root, real x, real y, real z)
{
	global const dev_pattern *pt = &sc->patterns[root];
	float3 q = texture_pattern_point(pt, (float3)((float)x, (float)y, (float)z));
	return (real)function_pattern_value(sc, pt, q, FUNCTION_NO_NORMAL, -FUNCTION_NO_NORMAL);
}

/* One channel of a pigment function's colour at p: red, green, blue, filter,
 * transmit, or (5) its grey, POV-Ray's weights of the channels. */
static real function_pigment(const scene_data *sc, int root, int channel, real x, real y, real z)
{
	pigment_colour c = function_pigment_tree(sc, root, (float3)((float)x, (float)y, (float)z), (float2)(0.0f),
	                                         FUNCTION_NO_NORMAL, -FUNCTION_NO_NORMAL);
	switch (channel) {
	case 0: return (real)c.rgb.x;
	case 1: return (real)c.rgb.y;
	case 2: return (real)c.rgb.z;
	case 3: return (real)c.filter;
	case 4: return (real)c.transmit;
	default: return (real)(0.297f * c.rgb.x + 0.589f * c.rgb.y + 0.114f * c.rgb.z);
	}
}
