/* ast.h: the syntax tree the parser builds and the evaluator walks.
 *
 * The tree is generic: a block is a keyword with a list of items, an item is an
 * expression, a block, a keyword with one argument, a flag or a directive. Which
 * items a block accepts is the evaluator's business (it knows the types), so the
 * grammar stays small and conflict-free and errors say "'location' is not valid in
 * a sphere" rather than "syntax error". Directives are nodes too (#if holds its
 * branches, #while its body): the evaluator runs them, the lexer never does. Every
 * node carries its source location. */
#ifndef ECLAT_AST_H
#define ECLAT_AST_H

#include <stdio.h>

#include "diag.h"

/* Keyword classes decide the grammar's shape around a keyword. */
enum kw_class {
	KWC_BLOCK,   /* KW { ITEMS }        sphere { <0,0,0>, 1 } */
	KWC_ARG,     /* KW EXPRESSION       translate <1,0,0>; also KW { ITEMS }: reflection { 0.1 } */
	KWC_FLAG,    /* KW                  no_shadow; what may follow is read as the next items */
	KWC_COLOR,   /* KW EXPRESSION       color Red: no-op, marks a colour */
	KWC_RGB,     /* KW EXPRESSION       rgb <1,0,0> */
	KWC_COMP,    /* KW EXPRESSION       color red 1 green 0.5; also .red */
	KWC_FUNC,    /* KW ( ARGS )         sqrt(2) */
	KWC_SPECIAL, /* a token of its own: texture array function deprecated once */
};

/* Every keyword the lexer knows, POV-Ray 3.7's spelling. ORDER: none; the lexer
 * looks names up in this table and tests/man.test reads it (one X a line). */
#define AST_KEYWORDS(X) \
	X(BACKGROUND, "background", BLOCK) \
	X(BOUNDED_BY, "bounded_by", BLOCK) \
	X(BOX, "box", BLOCK) \
	X(CAMERA, "camera", BLOCK) \
	X(CLIPPED_BY, "clipped_by", BLOCK) \
	X(DIFFERENCE, "difference", BLOCK) \
	X(COLOR_MAP, "color_map", BLOCK) \
	X(COLOUR_MAP, "colour_map", BLOCK) \
	X(FACE_INDICES, "face_indices", BLOCK) \
	X(FINISH, "finish", BLOCK) \
	X(FOG, "fog", BLOCK) \
	X(RAINBOW, "rainbow", BLOCK) \
	X(GLOBAL_SETTINGS, "global_settings", BLOCK) \
	X(INTERIOR, "interior", BLOCK) \
	X(INTERSECTION, "intersection", BLOCK) \
	X(LIGHT_SOURCE, "light_source", BLOCK) \
	X(LOOKS_LIKE, "looks_like", BLOCK) \
	X(MATERIAL, "material", BLOCK) \
	X(MEDIA, "media", BLOCK) \
	X(SCATTERING, "scattering", BLOCK) \
	X(DENSITY, "density", BLOCK) \
	X(DENSITY_MAP, "density_map", BLOCK) \
	X(MERGE, "merge", BLOCK) \
	X(MESH, "mesh", BLOCK) \
	X(MESH2, "mesh2", BLOCK) \
	X(NORMAL, "normal", BLOCK) \
	X(NORMAL_INDICES, "normal_indices", BLOCK) \
	X(NORMAL_MAP, "normal_map", BLOCK) \
	X(NORMAL_VECTORS, "normal_vectors", BLOCK) \
	X(OBJECT, "object", BLOCK) \
	X(PIGMENT, "pigment", BLOCK) \
	X(PIGMENT_MAP, "pigment_map", BLOCK) \
	X(PLANE, "plane", BLOCK) \
	X(SKY_SPHERE, "sky_sphere", BLOCK) \
	X(SMOOTH_TRIANGLE, "smooth_triangle", BLOCK) \
	X(SPHERE, "sphere", BLOCK) \
	X(TEXTURE_LIST, "texture_list", BLOCK) \
	X(TEXTURE_MAP, "texture_map", BLOCK) \
	X(TRIANGLE, "triangle", BLOCK) \
	X(UNION, "union", BLOCK) \
	X(UV_INDICES, "uv_indices", BLOCK) \
	X(VERTEX_VECTORS, "vertex_vectors", BLOCK) \
	X(ADAPTIVE, "adaptive", ARG) \
	X(ADC_BAILOUT, "adc_bailout", ARG) \
	X(AGATE_TURB, "agate_turb", ARG) \
	X(AMBIENT, "ambient", ARG) \
	X(AMBIENT_LIGHT, "ambient_light", ARG) \
	X(ANGLE, "angle", ARG) \
	X(ARC_ANGLE, "arc_angle", ARG) \
	X(APERTURE, "aperture", ARG) \
	X(AREA_LIGHT, "area_light", ARG) \
	X(ASSUMED_GAMMA, "assumed_gamma", ARG) \
	X(BLUR_SAMPLES, "blur_samples", ARG) \
	X(BRICK_SIZE, "brick_size", ARG) \
	X(BRILLIANCE, "brilliance", ARG) \
	X(CAUSTICS, "caustics", ARG) \
	X(CRAND, "crand", ARG) \
	X(DIFFUSE, "diffuse", ARG) \
	X(DIRECTION, "direction", ARG) \
	X(DISPERSION, "dispersion", ARG) \
	X(DISTANCE, "distance", ARG) \
	X(EMISSION, "emission", ARG) \
	X(EXPONENT, "exponent", ARG) \
	X(FADE_COLOR, "fade_color", ARG) \
	X(FADE_COLOUR, "fade_colour", ARG) \
	X(FADE_DISTANCE, "fade_distance", ARG) \
	X(FADE_POWER, "fade_power", ARG) \
	X(FALLOFF, "falloff", ARG) \
	X(FALLOFF_ANGLE, "falloff_angle", ARG) \
	X(FOCAL_POINT, "focal_point", ARG) \
	X(FOG_ALT, "fog_alt", ARG) \
	X(ABSORPTION, "absorption", ARG) \
	X(INTERVALS, "intervals", ARG) \
	X(SAMPLES, "samples", ARG) \
	X(METHOD, "method", ARG) \
	X(CONFIDENCE, "confidence", ARG) \
	X(VARIANCE, "variance", ARG) \
	X(RATIO, "ratio", ARG) \
	X(AA_LEVEL, "aa_level", ARG) \
	X(AA_THRESHOLD, "aa_threshold", ARG) \
	X(ECCENTRICITY, "eccentricity", ARG) \
	X(EXTINCTION, "extinction", ARG) \
	X(FOG_OFFSET, "fog_offset", ARG) \
	X(FOG_TYPE, "fog_type", ARG) \
	X(FREQUENCY, "frequency", ARG) \
	X(GRADIENT, "gradient", ARG) \
	X(INSIDE_VECTOR, "inside_vector", ARG) \
	X(IOR, "ior", ARG) \
	X(LAMBDA, "lambda", ARG) \
	X(LOCATION, "location", ARG) \
	X(LOOK_AT, "look_at", ARG) \
	X(MATRIX, "matrix", ARG) \
	X(MAX_TRACE_LEVEL, "max_trace_level", ARG) \
	X(MORTAR, "mortar", ARG) \
	X(OCTAVES, "octaves", ARG) \
	X(OMEGA, "omega", ARG) \
	X(PHASE, "phase", ARG) \
	X(PHONG, "phong", ARG) \
	X(PHONG_SIZE, "phong_size", ARG) \
	X(POINT_AT, "point_at", ARG) \
	X(RADIUS, "radius", ARG) \
	X(REFLECTION, "reflection", ARG) \
	X(RIGHT, "right", ARG) \
	X(ROTATE, "rotate", ARG) \
	X(ROUGHNESS, "roughness", ARG) \
	X(SCALE, "scale", ARG) \
	X(SKY, "sky", ARG) \
	X(SPECULAR, "specular", ARG) \
	X(SPIRAL1, "spiral1", ARG) \
	X(SPIRAL2, "spiral2", ARG) \
	X(TIGHTNESS, "tightness", ARG) \
	X(TRANSFORM, "transform", ARG) \
	X(TRANSLATE, "translate", ARG) \
	X(TURB_DEPTH, "turb_depth", ARG) \
	X(TURBULENCE, "turbulence", ARG) \
	X(UP, "up", ARG) \
	X(WIDTH, "width", ARG) \
	X(UV_VECTORS, "uv_vectors", ARG) \
	X(AGATE, "agate", FLAG) \
	X(BOXED, "boxed", FLAG) \
	X(BOZO, "bozo", FLAG) \
	X(BRICK, "brick", FLAG) \
	X(BUMPS, "bumps", FLAG) \
	X(CELLS, "cells", FLAG) \
	X(CHECKER, "checker", FLAG) \
	X(CIRCULAR, "circular", FLAG) \
	X(CONSERVE_ENERGY, "conserve_energy", FLAG) \
	X(CRACKLE, "crackle", FLAG) \
	X(CUBIC_WAVE, "cubic_wave", FLAG) \
	X(CYLINDRICAL, "cylindrical", FLAG) \
	X(DENTS, "dents", FLAG) \
	X(DOUBLE_ILLUMINATE, "double_illuminate", FLAG) \
	X(FACETS, "facets", FLAG) \
	X(FISHEYE, "fisheye", FLAG) \
	X(FRESNEL, "fresnel", FLAG) \
	X(GRANITE, "granite", FLAG) \
	X(HEXAGON, "hexagon", FLAG) \
	X(HOLLOW, "hollow", FLAG) \
	X(INVERSE, "inverse", FLAG) \
	X(JITTER, "jitter", FLAG) \
	X(LEOPARD, "leopard", FLAG) \
	X(MARBLE, "marble", FLAG) \
	X(MEDIA_ATTENUATION, "media_attenuation", FLAG) \
	X(MEDIA_INTERACTION, "media_interaction", FLAG) \
	X(METALLIC, "metallic", FLAG) \
	X(NO_IMAGE, "no_image", FLAG) \
	X(NO_REFLECTION, "no_reflection", FLAG) \
	X(NO_SHADOW, "no_shadow", FLAG) \
	X(OMNIMAX, "omnimax", FLAG) \
	X(ONION, "onion", FLAG) \
	X(ORIENT, "orient", FLAG) \
	X(ORTHOGRAPHIC, "orthographic", FLAG) \
	X(PANORAMIC, "panoramic", FLAG) \
	X(PARALLEL, "parallel", FLAG) \
	X(PERSPECTIVE, "perspective", FLAG) \
	X(PLANAR, "planar", FLAG) \
	X(POLY_WAVE, "poly_wave", FLAG) \
	X(QUILTED, "quilted", FLAG) \
	X(RADIAL, "radial", FLAG) \
	X(RAMP_WAVE, "ramp_wave", FLAG) \
	X(RIPPLES, "ripples", FLAG) \
	X(SCALLOP_WAVE, "scallop_wave", FLAG) \
	X(SHADOWLESS, "shadowless", FLAG) \
	X(SINE_WAVE, "sine_wave", FLAG) \
	X(SPHERICAL, "spherical", FLAG) \
	X(SPOTLIGHT, "spotlight", FLAG) \
	X(SPOTTED, "spotted", FLAG) \
	X(TRIANGLE_WAVE, "triangle_wave", FLAG) \
	X(ULTRA_WIDE_ANGLE, "ultra_wide_angle", FLAG) \
	X(UV_MAPPING, "uv_mapping", FLAG) \
	X(WAVES, "waves", FLAG) \
	X(WOOD, "wood", FLAG) \
	X(WRINKLES, "wrinkles", FLAG) \
	X(COLOR, "color", COLOR) \
	X(COLOUR, "colour", COLOR) \
	X(RGB, "rgb", RGB) \
	X(RGBF, "rgbf", RGB) \
	X(RGBFT, "rgbft", RGB) \
	X(RGBT, "rgbt", RGB) \
	X(SRGB, "srgb", RGB) \
	X(SRGBF, "srgbf", RGB) \
	X(SRGBFT, "srgbft", RGB) \
	X(SRGBT, "srgbt", RGB) \
	X(RED, "red", COMP) \
	X(GREEN, "green", COMP) \
	X(BLUE, "blue", COMP) \
	X(FILTER, "filter", COMP) \
	X(TRANSMIT, "transmit", COMP) \
	X(GRAY, "gray", COMP) \
	X(ABS, "abs", FUNC) \
	X(ACOS, "acos", FUNC) \
	X(ACOSH, "acosh", FUNC) \
	X(ASC, "asc", FUNC) \
	X(ASIN, "asin", FUNC) \
	X(ASINH, "asinh", FUNC) \
	X(ATAN, "atan", FUNC) \
	X(ATAN2, "atan2", FUNC) \
	X(ATANH, "atanh", FUNC) \
	X(BITWISE_AND, "bitwise_and", FUNC) \
	X(BITWISE_OR, "bitwise_or", FUNC) \
	X(BITWISE_XOR, "bitwise_xor", FUNC) \
	X(CEIL, "ceil", FUNC) \
	X(CHR, "chr", FUNC) \
	X(CONCAT, "concat", FUNC) \
	X(COS, "cos", FUNC) \
	X(COSH, "cosh", FUNC) \
	X(DEFINED, "defined", FUNC) \
	X(DEGREES, "degrees", FUNC) \
	X(DIMENSION_SIZE, "dimension_size", FUNC) \
	X(DIMENSIONS, "dimensions", FUNC) \
	X(DIV, "div", FUNC) \
	X(EXP, "exp", FUNC) \
	X(FILE_EXISTS, "file_exists", FUNC) \
	X(FLOOR, "floor", FUNC) \
	X(INSIDE, "inside", FUNC) \
	X(INT, "int", FUNC) \
	X(LN, "ln", FUNC) \
	X(LOG, "log", FUNC) \
	X(MAX, "max", FUNC) \
	X(MAX_EXTENT, "max_extent", FUNC) \
	X(MIN, "min", FUNC) \
	X(MIN_EXTENT, "min_extent", FUNC) \
	X(MOD, "mod", FUNC) \
	X(POW, "pow", FUNC) \
	X(RADIANS, "radians", FUNC) \
	X(RAND, "rand", FUNC) \
	X(SEED, "seed", FUNC) \
	X(SELECT, "select", FUNC) \
	X(SIN, "sin", FUNC) \
	X(SINH, "sinh", FUNC) \
	X(SQRT, "sqrt", FUNC) \
	X(STR, "str", FUNC) \
	X(STRCMP, "strcmp", FUNC) \
	X(STRLEN, "strlen", FUNC) \
	X(STRLWR, "strlwr", FUNC) \
	X(STRUPR, "strupr", FUNC) \
	X(SUBSTR, "substr", FUNC) \
	X(TAN, "tan", FUNC) \
	X(TANH, "tanh", FUNC) \
	X(TRACE, "trace", FUNC) \
	X(VAL, "val", FUNC) \
	X(VAXIS_ROTATE, "vaxis_rotate", FUNC) \
	X(VCROSS, "vcross", FUNC) \
	X(VDOT, "vdot", FUNC) \
	X(VLENGTH, "vlength", FUNC) \
	X(VNORMALIZE, "vnormalize", FUNC) \
	X(VROTATE, "vrotate", FUNC) \
	X(VSTR, "vstr", FUNC) \
	X(VTURBULENCE, "vturbulence", FUNC) \
	X(ARRAY, "array", SPECIAL) \
	X(DEPRECATED, "deprecated", SPECIAL) \
	X(FUNCTION, "function", SPECIAL) \
	X(ONCE, "once", SPECIAL) \
	X(TEXTURE, "texture", SPECIAL)

/* Contextual words: keywords only where noted and identifiers everywhere else,
 * as POV-Ray reserves none of them and its scenes use them as names. The lexer
 * does not know them; the evaluator recognises them where they stand.
 * tests/man.test reads these lines (one AST_WORD_ a line).
 *   file: right inside a mesh, mesh { file "NAME" } (eval_object.c)
 *   spline and its types: spline { linear_spline ... }, S(T, cubic_spline)
 *   (eval_spline.c)
 *   the patterns and pattern modifiers POV-Ray has no keyword token for, in a
 *   pigment: aoi, cubic, square, triangular, noise_generator, no_bump_scale,
 *   metric, form, offset, solid, control0, control1, and in warp { }: repeat, offset, flip,
 *   black_hole, strength (eval_pattern.c); in normal { }: bump_size, accuracy,
 *   slope_map (eval_material.c); in image_map { }: image_map itself, the file
 *   formats (png, jpeg, tiff, exr, hdr, gif, tga, ppm, sys), map_type,
 *   interpolate, gamma, premultiplied, all, use_color, use_colour, use_index
 *   (eval_pattern.c)
 *   open: in a shape that takes it, cylinder { ... open } (eval_object.c)
 *   average: the pattern of a map's entries (eval_material.c)
 *   slope and altitude: the slope pattern, slope { V altitude V } (eval_pattern.c)
 *   interior_texture: an object's, interior_texture { ... } (eval_object.c)
 *   tiles and tile2: in a texture, tiles { TEXTURE tile2 TEXTURE } (eval_material.c)
 *   mesh_camera and smooth: in a camera, mesh_camera { ... smooth } (eval_camera_mesh.c)
 *   charset and its sets ascii, utf8, sys: in global_settings (eval_world.c)
 * The shapes' own names are not here: the shapes' table has them (src/shape.h),
 * and tests/man.test reads them from src/shape_*.c. */
#define AST_WORD_MESH_FILE "file"
#define AST_WORD_AVERAGE "average"
#define AST_WORD_SLOPE "slope"
#define AST_WORD_ALTITUDE "altitude"
#define AST_WORD_INTERIOR_TEXTURE "interior_texture"
#define AST_WORD_TILES "tiles"
#define AST_WORD_TILE2 "tile2"
#define AST_WORD_MESH_CAMERA "mesh_camera"
#define AST_WORD_SMOOTH "smooth"
#define AST_WORD_CHARSET "charset"
#define AST_WORD_ASCII "ascii"
#define AST_WORD_UTF8 "utf8"
#define AST_WORD_SYS "sys"
#define AST_WORD_AOI "aoi"
#define AST_WORD_CUBIC "cubic"
#define AST_WORD_TOROIDAL "toroidal"      /* a warp { }: the mapping warps' words */
#define AST_WORD_ORIENTATION "orientation"
#define AST_WORD_DIST_EXP "dist_exp"
#define AST_WORD_MAJOR_RADIUS "major_radius"
#define AST_WORD_SQUARE "square"
#define AST_WORD_TRIANGULAR "triangular"
#define AST_WORD_NOISE_GENERATOR "noise_generator"
#define AST_WORD_NUMBER_OF_WAVES "number_of_waves"
#define AST_WORD_TILING "tiling"
#define AST_WORD_PAVEMENT "pavement"
#define AST_WORD_NUMBER_OF_SIDES "number_of_sides"
#define AST_WORD_NUMBER_OF_TILES "number_of_tiles"
#define AST_WORD_PATTERN "pattern"
#define AST_WORD_IRID "irid"
#define AST_WORD_IRID_WAVELENGTH "irid_wavelength"
#define AST_WORD_THICKNESS "thickness"
#define AST_WORD_NO_BUMP_SCALE "no_bump_scale"
#define AST_WORD_METRIC "metric"
#define AST_WORD_FORM "form"
#define AST_WORD_OFFSET "offset"
#define AST_WORD_SOLID "solid"
#define AST_WORD_CONTROL0 "control0"
#define AST_WORD_CONTROL1 "control1"
#define AST_WORD_WARP "warp"
#define AST_WORD_REPEAT "repeat"
#define AST_WORD_FLIP "flip"
#define AST_WORD_BLACK_HOLE "black_hole"
#define AST_WORD_STRENGTH "strength"
/* sphere_sweep { } (eval_sweep.c) */
#define AST_WORD_SPHERE_SWEEP "sphere_sweep"
#define AST_WORD_B_SPLINE "b_spline"
#define AST_WORD_TOLERANCE "tolerance"
/* parametric { } (eval_parametric.c); accuracy, max_gradient and contained_by are above */
#define AST_WORD_PARAMETRIC "parametric"
#define AST_WORD_PRECOMPUTE "precompute"
#define AST_WORD_HIERARCHY "hierarchy"
/* height_field { } (eval_hfield.c) */
#define AST_WORD_HEIGHT_FIELD "height_field"
#define AST_WORD_SMOOTH "smooth"
#define AST_WORD_WATER_LEVEL "water_level"
/* bicubic_patch { } (eval_bicubic.c) */
#define AST_WORD_BICUBIC_PATCH "bicubic_patch"
#define AST_WORD_TYPE "type"
#define AST_WORD_FLATNESS "flatness"
#define AST_WORD_U_STEPS "u_steps"
#define AST_WORD_V_STEPS "v_steps"
#define AST_WORD_BUMP_SIZE "bump_size"
#define AST_WORD_ACCURACY "accuracy"
#define AST_WORD_SLOPE_MAP "slope_map"
#define AST_WORD_SPLINE "spline"
#define AST_WORD_LINEAR_SPLINE "linear_spline"
#define AST_WORD_QUADRATIC_SPLINE "quadratic_spline"
#define AST_WORD_CUBIC_SPLINE "cubic_spline"
#define AST_WORD_NATURAL_SPLINE "natural_spline"
#define AST_WORD_IMAGE_MAP "image_map"
#define AST_WORD_MAP_TYPE "map_type"
#define AST_WORD_INTERPOLATE "interpolate"
#define AST_WORD_GAMMA "gamma"
#define AST_WORD_PREMULTIPLIED "premultiplied"
#define AST_WORD_ALL "all"
#define AST_WORD_USE_COLOR "use_color"
#define AST_WORD_USE_COLOUR "use_colour"
#define AST_WORD_USE_INDEX "use_index"
#define AST_WORD_USE_ALPHA "use_alpha"
#define AST_WORD_IMAGE_PATTERN "image_pattern"
#define AST_WORD_BUMP_MAP "bump_map"
#define AST_WORD_MATERIAL_MAP "material_map"
#define AST_WORD_DENSITY_FILE "density_file"
#define AST_WORD_DF3 "df3"
#define AST_WORD_PNG "png"
#define AST_WORD_JPEG "jpeg"
#define AST_WORD_TIFF "tiff"
#define AST_WORD_EXR "exr"
#define AST_WORD_HDR "hdr"
#define AST_WORD_GIF "gif"
#define AST_WORD_TGA "tga"
#define AST_WORD_PPM "ppm"
#define AST_WORD_SYS "sys"
#define AST_WORD_POT "pot"   /* a height field's Fractint file (eval_hfield.c) */
/* polygon, prism, text and their words (eval_outline.c); open and sturm after
 * any shape that takes them (eval_object.c) */
#define AST_WORD_POLYGON "polygon"
#define AST_WORD_PRISM "prism"
#define AST_WORD_TEXT "text"
#define AST_WORD_LINEAR_SWEEP "linear_sweep"
#define AST_WORD_CONIC_SWEEP "conic_sweep"
#define AST_WORD_BEZIER_SPLINE "bezier_spline"
#define AST_WORD_TTF "ttf"
#define AST_WORD_INTERNAL "internal"
#define AST_WORD_OPEN "open"
#define AST_WORD_STURM "sturm"
/* quadric, sor, lathe (shape_quadric.c, eval_outline.c) */
#define AST_WORD_QUADRIC "quadric"
#define AST_WORD_SOR "sor"
#define AST_WORD_LATHE "lathe"
#define AST_WORD_TORUS "torus"
#define AST_WORD_SUPERELLIPSOID "superellipsoid"
#define AST_WORD_ISOSURFACE "isosurface"
/* isosurface's own words (eval_isosurface.c) */
#define AST_WORD_CONTAINED_BY "contained_by"
#define AST_WORD_THRESHOLD "threshold"
#define AST_WORD_MAX_GRADIENT "max_gradient"
#define AST_WORD_MAX_TRACE "max_trace"
#define AST_WORD_ALL_INTERSECTIONS "all_intersections"
#define AST_WORD_POLARITY "polarity"
#define AST_WORD_EVALUATE "evaluate"
/* a term of polynomial { Order, xyz(I, J, K): C ... } (eval_poly.c) */
#define AST_WORD_XYZ "xyz"
/* blob { } (eval_blob.c) */
#define AST_WORD_BLOB "blob"
#define AST_WORD_COMPONENT "component"
#define AST_WORD_STRENGTH "strength"
/* the fractal patterns and their words (eval_fractal.c) */
#define AST_WORD_MANDEL "mandel"
#define AST_WORD_JULIA "julia"
#define AST_WORD_MAGNET "magnet"
#define AST_WORD_EXTERIOR "exterior"
#define AST_WORD_JULIA_FRACTAL "julia_fractal"
#define AST_WORD_QUATERNION "quaternion"
#define AST_WORD_HYPERCOMPLEX "hypercomplex"
#define AST_WORD_SQR "sqr"
#define AST_WORD_CUBE "cube"
#define AST_WORD_MAX_ITERATION "max_iteration"
#define AST_WORD_PRECISION "precision"
#define AST_WORD_SLICE "slice"

enum ast_keyword {
	KW_UNKNOWN = -2, /* NAME { ... } with a NAME that is no keyword: str holds it */
	KW_FILE = -1,    /* the block that holds a whole file */
#define X(id, name, cls) KW_##id,
	AST_KEYWORDS(X)
#undef X
	KW_COUNT
};

/* Operators of AST_BINARY that are not one character. */
enum { OP_LE = 256, OP_GE, OP_NE };

typedef enum {
	/* expressions; ORDER: AST_IS_EXPRESSION */
	AST_NUMBER,   /* num */
	AST_STRING,   /* str */
	AST_IDENT,    /* str */
	AST_VECTOR,   /* kids: the components */
	AST_BINARY,   /* op (+ - * / < > = & | OP_LE OP_GE OP_NE), kids: left right */
	AST_UNARY,    /* op (- + !), kids: operand */
	AST_COLOR,    /* kw; color/rgb...: kids operand; red...: kids [base] value */
	AST_COND,     /* kids: condition, then, else */
	AST_MEMBER,   /* str = x y z u v t red green blue filter transmit gray, kids: operand */
	AST_INDEX,    /* kids: array, index */
	AST_CALL,     /* str = macro or function name, kids: arguments */
	AST_FUNC,     /* kw = built-in function, kids: arguments */
	AST_IFEXPR,   /* (#if (C) ITEMS [#else ITEMS] #end): kids as AST_IF; a branch gives one value */
	/* everything else */
	AST_BLOCK,    /* kw, kids: items; op 'B': the kids are another block's (#if (C) merge { #else union { #end) */
	AST_ARG,      /* kw, kids: argument */
	AST_FLAG,     /* kw */
	AST_ENTRY,    /* [ ITEMS ] of a colour_map and the other maps, kids: items */
	AST_ARRAY,    /* array[N]...: kids: dimensions (AST_BLOCK), [initialiser (AST_INIT)] */
	AST_INIT,     /* { ITEMS } of an array initialiser, kids: items or AST_INIT */
	AST_FUNCTION, /* function [(PARAMS)] { BODY }: kids: parameters (AST_BLOCK of AST_IDENT), body */
	AST_DECLARE,  /* str = name, op = 'd' (#declare) or 'l' (#local), kids: value, [indices...] */
	AST_INCLUDE,  /* kids: file name expression */
	AST_MACRO,    /* str = name, kids: parameters (AST_BLOCK of AST_IDENT), body */
	AST_IF,       /* op 'i' #if, 'd' #ifdef, 'n' #ifndef; kids: cond, body, [cond, body]..., [else] */
	AST_WHILE,    /* kids: condition, body */
	AST_FOR,      /* str = variable, kids: start, end, [step], body */
	AST_SWITCH,   /* kids: value, body (items with AST_CASE, AST_RANGE, AST_ELSE among them) */
	AST_CASE,     /* kids: value */
	AST_RANGE,    /* kids: low, high */
	AST_ELSE,     /* #else of a #switch */
	AST_BREAK,
	AST_UNDEF,    /* str = name */
	AST_VERSION,  /* kids: version */
	AST_DEFAULT,  /* kids: items */
	AST_MESSAGE,  /* op 'd' #debug, 'w' #warning, 'e' #error; kids: text */
	AST_FILE_IO,  /* str = fopen (kids: handle, name, mode), fclose (handle), read and write
	               * (kids: handle, then the items) */
} ast_kind;

#define AST_IS_EXPRESSION(k) ((k) <= AST_IFEXPR)

typedef struct ast_node {
	ast_kind kind;
	src_loc loc;
	int kw;      /* enum ast_keyword */
	int op;      /* operator character or OP_ */
	double num;
	char *str;
	struct ast_node **kids;
	int n_kids, cap_kids;
	int depth;   /* 1 + the deepest kid's: the parser refuses trees deeper than AST_MAX_DEPTH */
} ast_node;

/* Every stage walks the tree recursively; this bounds the recursion. */
#define AST_MAX_DEPTH 1000

/* Keyword table look-ups. */
int ast_keyword_lookup(const char *name, enum kw_class *cls); /* -1 when not a keyword */
const char *ast_keyword_name(int kw);
/* An operator as written: "+", "<=", "!=" ... */
const char *ast_op_name(int op);
enum kw_class ast_keyword_class(int kw);

/* Constructors, one per grammar action. They take ownership of their arguments and
 * exit with a message on out of memory (a parser cannot recover from that). */
ast_node *ast_new(ast_kind kind, src_loc loc);
ast_node *ast_number(src_loc loc, double v);
ast_node *ast_text(ast_kind kind, src_loc loc, char *s);
ast_node *ast_op(ast_kind kind, src_loc loc, int op, ast_node *a, ast_node *b);
ast_node *ast_op3(ast_kind kind, src_loc loc, int op, ast_node *a, ast_node *b, ast_node *c);
ast_node *ast_keyword(ast_kind kind, src_loc loc, int kw, ast_node *arg);
ast_node *ast_named(ast_kind kind, src_loc loc, char *name, ast_node *a, ast_node *b);
ast_node *ast_declare(src_loc loc, int op, ast_node *target, ast_node *value);
ast_node *ast_append(ast_node *list, ast_node *kid);
/* Moves the kids of b to the end of a, frees b. */
ast_node *ast_concat(ast_node *a, ast_node *b);
/* Sets a block's keyword (or name, for KW_UNKNOWN) and location. */
ast_node *ast_block(ast_node *items, int kw, char *name, src_loc loc);
/* #if (C) THEN... HEAD1 { #else ELSE... HEAD2 { #end BODY }: an #if whose branches
 * end with the blocks HEAD1 { BODY } and HEAD2 { BODY }, which share BODY. */
ast_node *ast_if_heads(src_loc loc, ast_node *cond, ast_node *then, ast_node *head1, ast_node *els,
                       ast_node *head2, ast_node *body);

void ast_free(ast_node *n);
/* Writes the tree as S-expressions with locations, for --dump-ast and golden tests. */
void ast_dump(const ast_node *n, FILE *out);

#endif
