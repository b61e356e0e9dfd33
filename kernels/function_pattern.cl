/* function_pattern.cl: the pattern and pigment functions that the scene's
 * generated functions call (FOP_PATTERN, FOP_PIGMENT: POV-Ray's f_pattern and
 * f_pigment), on the pattern trees lowering made for them (with no
 * transformation around them: a function's x, y, z are the pattern's space
 * before its own transformations).
 *
 * OpenCL C has no recursion, so the call graph must stay acyclic: a pattern
 * reaches a function (pattern_at, PATTERN_FUNCTION), the function reaches
 * these, and these reach the next level's functions (below) or, at the last
 * level, only pattern_plain, which runs no function pattern. Evaluation
 * refuses deeper nests than SCENE_FUNCTION_LEVELS_MAX (eval_function.c). */

/* What aoi and slope see here: POV-Ray gives the function no surface. */
#define FUNCTION_NO_NORMAL ((float3)(0.0f, 0.0f, 1.0f))

/* The levels of functions (lower_function.c: scene_function_levels): a
 * function's pattern may be a function pattern, whose function's pattern may
 * be one... OpenCL C has no recursion, so each level L >= 2 has its own copy
 * of the functions (scene_fn<N>_<L>, lowering writes them) and of what
 * follows, made by these macros: a level's functions read their patterns
 * with pattern_at_<L + 1>, which runs level L + 1's functions, and the last
 * level's with pattern_plain, which runs none. FUNCTION_LEVELS (the build's
 * option) is 1 when no function pattern is under a function. */
#ifndef FUNCTION_LEVELS
#define FUNCTION_LEVELS 1
#endif

static inline float function_plain_at(const scene_data *sc, global const dev_pattern *pt, float3 q, float3 n, float3 d)
{
	return pattern_plain(pt, sc->warps, q, n, d);
}

/* pattern_at for the patterns of level L - 1's functions: a function pattern
 * runs level L's functions. */
#define FUNCTION_PATTERN_AT(L) \
static real scene_function_at_##L(const scene_data *sc, int f, real x, real y, real z); \
static float pattern_at_##L(const scene_data *sc, global const dev_pattern *pt, float3 q, float3 n, float3 d) \
{ \
	if (pt->kind != PATTERN_FUNCTION) \
		return pattern_plain(pt, sc->warps, q, n, d); \
	float v = (float)scene_function_at_##L(sc, (int)pt->params[0].x, (real)q.x, (real)q.y, (real)q.z); \
	if (v > 1.0f)   /* as pattern_at */ \
		v = fmod(v, 1.0f); \
	return pattern_wave(pt, v); \
}

/* A level's pattern and pigment functions (SUFFIX: empty for level 1, else
 * _L), reading patterns with AT. */
#define FUNCTION_PATTERN_LEVEL(SUFFIX, AT) \
static inline float function_pattern_value##SUFFIX(const scene_data *sc, global const dev_pattern *pt, float3 q, \
                                                   float3 n, float3 d) \
{ \
	return AT(sc, pt, pattern_warp_point(pt, sc->warps, q), n, d); \
} \
TEXTURE_PIGMENT_TREE(function_pigment_tree##SUFFIX, function_pattern_value##SUFFIX) \
/* A pattern function's value at p: its pattern's, through its warps. */ \
static real function_pattern##SUFFIX(const scene_data *sc, int root, real x, real y, real z) \
{ \
	global const dev_pattern *pt = &sc->patterns[root]; \
	float3 q = texture_pattern_point(pt, (float3)((float)x, (float)y, (float)z)); \
	return (real)function_pattern_value##SUFFIX(sc, pt, q, FUNCTION_NO_NORMAL, -FUNCTION_NO_NORMAL); \
} \
/* One channel of a pigment function's colour at p: red, green, blue, filter, \
 * transmit, or (5) its grey, POV-Ray's weights of the channels. */ \
static real function_pigment##SUFFIX(const scene_data *sc, int root, int channel, real x, real y, real z) \
{ \
	pigment_colour c = function_pigment_tree##SUFFIX(sc, root, (float3)((float)x, (float)y, (float)z), \
	                                                 (float2)(0.0f), FUNCTION_NO_NORMAL, -FUNCTION_NO_NORMAL); \
	switch (channel) { \
	case 0: return (real)c.rgb.x; \
	case 1: return (real)c.rgb.y; \
	case 2: return (real)c.rgb.z; \
	case 3: return (real)c.filter; \
	case 4: return (real)c.transmit; \
	default: return (real)(0.297f * c.rgb.x + 0.589f * c.rgb.y + 0.114f * c.rgb.z); \
	} \
}

#if FUNCTION_LEVELS > 1
FUNCTION_PATTERN_AT(2)
FUNCTION_PATTERN_LEVEL(, pattern_at_2)
#else
FUNCTION_PATTERN_LEVEL(, function_plain_at)
#endif
