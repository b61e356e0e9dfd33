/* scene.h: the evaluated scene, independent of both the language and the device.
 *
 * Objects keep their object-space geometry and an object-to-world transform; the
 * lowering stage bakes them. Every entity keeps the location of the .scn text that
 * made it, so late errors still point at the source. */
#ifndef ECLAT_SCENE_H
#define ECLAT_SCENE_H

#include <stdbool.h>
#include <stdio.h>
#include "diag.h"
#include "../kernels/shared.h"   /* PATTERN_, WAVE_, WARP_ */

/* An affine transform: world = m * (p, 1), rows of a 3x4 matrix. */
typedef struct {
	double m[3][4];
} xform;

xform scene_xform_identity(void);
xform scene_xform_translate(const double v[3]);
xform scene_xform_scale(const double v[3]);
/* POV-Ray's rotate <a,b,c>: degrees about x, then y, then z, left-handed. */
xform scene_xform_rotate(const double deg[3]);
/* The transform that applies a, then b. */
xform scene_xform_then(const xform *a, const xform *b);
void scene_xform_point(const xform *t, const double p[3], double out[3]);
void scene_xform_vector(const xform *t, const double v[3], double out[3]);

/* A pattern pigment's map entry: a colour, or a nested pigment (a pigment_map
 * entry, or checker pigment { } pigment { }); in a pattern of whole textures
 * (scene_material.texture_map), a texture, with its average colour. */
typedef struct {
	double value;
	float colour[5];         /* rgb, filter, transmit */
	int pigment;             /* an index into scene.pigments, or -1: the colour */
	int texture;             /* a texture_map's: an index into scene.textures (set in those only) */
} scene_map_entry;

/* A warp { } of a pattern, its classic turbulence, or a transformation
 * (kernels/shared.h, dev_warp, which says in what order POV-Ray keeps them). */
#define SCENE_MAX_WARPS 16
typedef struct {
	int kind;                /* WARP_ */
	bool classic;            /* the turbulence written in the pattern itself */
	double a[4], b[4], c[4], d[4];
	xform xf;                /* WARP_TRANSFORM: the pattern's space to the outer one, as written */
} scene_warp;

/* A pigment with a pattern (src/eval_pattern.c): its kind, modifiers and map,
 * with POV-Ray 3.7's defaults. The scene keeps them in one pool, and a material
 * or a map entry refers to one by its index; a pigment in the pool is never
 * changed once made, so materials copied by value can share it. kind
 * PATTERN_SOLID holds a colour_map alone (a declared map). */
typedef struct {
	int kind;                /* PATTERN_ */
	int wave, noise_generator;   /* 1, 2 or 3; 0: global_settings' (scene_noise_generator) */
	double frequency, phase, wave_exponent;
	double params[2][4];     /* by kind, as dev_pattern's */
	double bump_size, accuracy;  /* a normal's: its amount (0.5) and accuracy (0.02) */
	double altitude[2];      /* slope's altitude range: low, width (0: none) */
	bool no_bump_scale;      /* a normal's transformations scale its bumps */
	bool uv;                 /* uv_mapping: its point is the surface's <u, v, 0>, moved by
	                          * its own transformations only, and so are its map's pigments */
	bool map_written;        /* its map was written, or is a list pattern's (checker...),
	                          * which POV-Ray always makes: a pattern that a later
	                          * pigment { } in the same texture starts keeps it */
	bool normal_map;         /* a normal's map entries are normals (pigment: the normal's
	                          * pattern, or -1: none), not its slope_map */
	scene_warp warps[SCENE_MAX_WARPS];  /* POV-Ray's list: the first applies first; the
	                          * transformations written in the pigment are among them */
	int n_warps;
	scene_map_entry *map;    /* by increasing value */
	int n_map;
	src_loc loc;
} scene_pigment;

/* An image of an image_map, read once however many pigments use it (keyed by
 * its resolved path and its gamma): the file's values, RGBA, top row first, and
 * how POV-Ray 3.7 decodes them (eval_pattern.c); lowering turns them into the
 * working gamma, which is known only at the scene's end. */
enum { SCENE_DECODE_NONE, SCENE_DECODE_SRGB, SCENE_DECODE_POWER, SCENE_DECODE_LINEAR };
typedef struct {
	char *key;               /* the resolved path, a tab, the gamma written ("" when none) */
	float *rgba;
	int width, height;
	int decode;              /* SCENE_DECODE_: NONE, the values are the working gamma's already */
	float gamma;             /* SCENE_DECODE_POWER's */
	bool gamma_given;        /* gamma written: decoded even with gamma correction off */
	bool premultiplied;      /* rgb is multiplied by alpha */
	bool data;               /* a bump_map's, image_pattern's or material_map's: decoded
	                          * only by a gamma written, never into the working gamma
	                          * (POV-Ray's); a material_map's red is its material numbers */
	float average[4];        /* rgb and alpha, as the file has them */
	float *filter;           /* each texel's filter, from its palette entry's (an image_map's
	                          * filter N, V), or NULL: none */
	bool palette;            /* the image_map's filter and transmit went into its palette */
	src_loc loc;
} scene_image;

/* uv_mapping of a whole texture: none; texture { uv_mapping ... }; the
 * object's uv_mapping (before its texture: its layers are uv_mapped too).
 * Either way the patterns see <u, v, 0> moved by the texture's own
 * transformations only (uv_xf), not by the object's after it, as in POV-Ray. */
enum { SCENE_UV_NONE = 0, SCENE_UV_TEXTURE, SCENE_UV_OBJECT };

/* A POV-Ray texture and interior, with POV-Ray 3.7's defaults
 * (scene_default_material). The path tracer turns these into a physically based
 * material (lower.c, documented in eclat-scene(5)); the Whitted integrator uses
 * them as POV-Ray does. */
typedef struct {
	float pigment[5];        /* red, green, blue, filter, transmit; default black; with a
	                          * pattern, its average colour */
	int pattern;             /* the pattern pigment (scene.pigments), or -1: pigment[] */
	int normal;              /* the normal's pattern (scene.pigments), or -1: none */
	float normal_amount;     /* a normal without a pattern yet (#default { normal {
	                          * bump_size 1.5 } }): the amount its pattern starts
	                          * with when one is written; 0: POV-Ray's 0.5 */
	xform tex_xf;            /* the texture's space to world (to the mesh's space for a
	                          * mesh's own textures): the transformations written after it */
	int uv;                  /* SCENE_UV_: whether its patterns are uv_mapped, and how placed */
	xform uv_xf;             /* with uv: the texture's own transformations */
	/* A pattern of whole textures, or layered textures: then pigment[] is their
	 * average and the finish the first's (or the top layer's), for what needs one
	 * texture; tex_xf places the pattern and its textures, or the layers. */
	int texture_map;         /* the pattern (scene.pigments) whose map's entries are
	                          * textures (scene_map_entry.texture), or -1 */
	int layers;              /* the top layer (scene.textures), or -1: not layered */
	int below;               /* in scene.textures, a layer's next layer down, or -1;
	                          * it shares the layer's outer space (tex_xf of the layers' owner) */
	int interior_texture;    /* an object's interior_texture, the texture of the side its
	                          * surface normal turns away from: 1 + its index in scene.textures,
	                          * 0: none (so that zeroed objects have none) */
	xform interior_xf;       /* the object's transformations written after interior_texture */
	/* finish */
	float ambient[3];        /* 0.1 */
	float diffuse;           /* 0.6 */
	float brilliance;        /* 1 */
	float emission[3];       /* 0 */
	float phong, phong_size; /* 0, 40 */
	float specular, roughness;          /* 0, 0.05 */
	float reflection[3];     /* reflection { min [, max] }: at normal incidence, 0 */
	float reflection_max[3]; /* at grazing incidence; equals reflection when one colour is given */
	float reflection_falloff;  /* 1 */
	float reflection_exponent; /* 1 */
	float metallic;          /* 0; "metallic" alone is 1: tints highlights */
	float reflection_metallic; /* 0: reflection { metallic }, tints reflections */
	bool reflection_fresnel; /* false */
	bool roughness_set;      /* roughness was given: metal reflections are rough */
	bool conserve_energy;    /* false */
	float crand;             /* 0: crand, the diffuse term's graininess */
	float irid;              /* 0: irid { Amount thickness T turbulence T }, thin-film tint */
	float irid_thickness, irid_turbulence; /* 0, 0 */
	/* interior */
	float ior;               /* 1 */
	float dispersion;        /* 1 */
	float fade_distance, fade_power; /* 0, 0: no absorption */
	float fade_color[3];     /* 0 */
	int media;               /* the interior's last media (scene.media) plus one; 0: none */
	float caustics;          /* 0: caustics as written (POV-Ray's power is 45 times it) */
} scene_material;

/* The shapes of the scene language, one row each: X(NAME, name) makes
 * SHAPE_NAME, whose class (parsing, bounds, trace(), lowering, --dump-scene)
 * is shape_name in src/shape_name.c (src/shape.h). What each keeps in a
 * scene_object:
 *   sphere: p[0] centre, radius;  triangle: p[0..2] corners;
 *   smooth_triangle: p[0..2] corners, n[0..2] normals;  box: p[0], p[1] opposite corners;
 *   plane: p[0] normal, radius = distance along it;
 *   mesh: mesh, an index into scene.meshes, shared by every copy;
 *   polygon, prism, text: outline, an index into scene.outlines (src/prism.h
 *   says what each keeps in p, n, radius and param);
 *   quadric: p[0..2] <A,B,C>, <D,E,F>, <G,H,I>, radius J;
 *   sor, lathe: outline, its points (src/revolve.h);
 *   cylinder: p[0] base, p[1] cap, radius, shape_flags SHAPE_OPEN;
 *   cone: p[0] base, radius its radius, p[1] cap, param[0] its radius, SHAPE_OPEN;
 *   disc: p[0] centre, p[1] normal, radius, param[0] the hole's radius (0: none);
 *   torus: radius the major radius, param[0] the minor;
 *   superellipsoid: p[0] <E, N, 0>;
 *   poly, cubic, quartic, polynomial: poly, an index into scene.polys;
 *   sphere_sweep: outline, its spheres as edges (x, y, z, radius), param[0] its
 *   spline (src/sweep.h), param[1] its tolerance;
 *   height_field, bicubic_patch, parametric: mesh, their triangles (or -1). */
#define SCENE_SHAPES(X) \
	X(SPHERE, sphere) \
	X(TRIANGLE, triangle) \
	X(SMOOTH_TRIANGLE, smooth_triangle) \
	X(BOX, box) \
	X(PLANE, plane) \
	X(MESH, mesh) \
	X(POLYGON, polygon) \
	X(PRISM, prism) \
	X(TEXT, text) \
	X(QUADRIC, quadric) \
	X(SOR, sor) \
	X(LATHE, lathe) \
	X(CYLINDER, cylinder) \
	X(CONE, cone) \
	X(DISC, disc) \
	X(TORUS, torus) \
	X(SUPERELLIPSOID, superellipsoid) \
	X(ISOSURFACE, isosurface) \
	X(POLY, poly) \
	X(CUBIC, cubic) \
	X(QUARTIC, quartic) \
	X(POLYNOMIAL, polynomial) \
	X(BLOB, blob) \
	X(HEIGHT_FIELD, height_field) \
	X(BICUBIC_PATCH, bicubic_patch) \
	X(JULIA_FRACTAL, julia_fractal) \
	X(SPHERE_SWEEP, sphere_sweep) \
	X(PARAMETRIC, parametric)
#define SCENE_SHAPE_ENUM_ROW(NAME, name) SHAPE_##NAME,
typedef enum { SCENE_SHAPES(SCENE_SHAPE_ENUM_ROW) SHAPE_KINDS } scene_shape;

/* Flags of a shape (scene_object.shape_flags): POV-Ray's open and sturm. */
enum { SHAPE_OPEN = 1, SHAPE_STURM = 2 };

/* POV-Ray's object flags. */
enum {
	OBJ_NO_SHADOW = 1, OBJ_NO_IMAGE = 2, OBJ_NO_REFLECTION = 4, OBJ_HOLLOW = 8,
	OBJ_DOUBLE_ILLUMINATE = 16,
};

typedef struct {
	scene_shape shape;
	double p[3][3];      /* object space, see scene_shape */
	double n[3][3];
	double radius;
	double param[4];     /* a shape's other numbers, as its class says */
	int shape_flags;     /* SHAPE_ */
	int csg;             /* 1 + the CSG object it is a leaf of (scene.csgs), or 0: it stands alone */
	bool clip;           /* a clipped_by shape: it only says what is inside, and is never seen */
	bool pattern;        /* a part of an object pattern's object (scene_csg.pattern): never seen */
	int mesh;
	int outline;         /* polygon, prism, text: an index into scene.outlines */
	int function;        /* isosurface: its function (scene.functions), -1 for none */
	int poly;            /* poly, cubic, quartic, polynomial: an index into scene.polys;
	                      * blob: into scene.blobs */
	xform xf;            /* object to world */
	scene_material material;
	bool textured;       /* false: takes the texture of an enclosing union, else the default */
	bool interior_set;   /* false: takes the interior of an enclosing union (POV-Ray
	                      * passes textures and interiors down apart) */
	int flags;           /* OBJ_ */
	src_loc loc;
} scene_object;

/* mesh and mesh2 (and mesh files), in object space. Declared once and placed many
 * times with object { }, it is stored once. A face's texture is an index into
 * mats, or -1 for the object's own texture. */
typedef struct {
	double (*v)[3];
	int n_v;
	double (*nrm)[3];    /* shading normals, may be empty */
	int n_nrm;
	double (*uv)[2];
	int n_uv;
	int (*face)[3];      /* vertex indices */
	int (*face_nrm)[3];  /* normal indices, or NULL */
	int (*face_uv)[3];   /* uv indices, or NULL */
	int *face_mat;       /* texture index per face, or NULL */
	int n_faces;
	scene_material *mats;
	int n_mats;
	double inside_vector[3];
	bool has_inside_vector;
	src_loc loc;
} scene_mesh;

/* A polynomial surface's coefficients (src/shape_poly.c), in POV-Ray's order:
 * the terms x^i y^j z^k with i + j + k <= order, i from order down to 0, then j,
 * then k, each from its highest down. Shared by every copy. */
typedef struct {
	int order;
	double *c;           /* (order+1)(order+2)(order+3)/6 of them */
	/* POV-Ray's bounded_by, when it is one sphere or box: a ray that misses it
	 * and starts outside it misses the poly. SCENE_BOUND_SPHERE: the unit
	 * sphere; SCENE_BOUND_BOX: the cube [-1, 1]^3; bound_xf maps it to world space. */
	int bound;
	xform bound_xf;
} scene_poly;
enum { SCENE_BOUND_NONE, SCENE_BOUND_SPHERE, SCENE_BOUND_BOX };

/* A blob's components (src/shape_blob.c), in the blob's space: each a sphere
 * (a == b) or a cylinder from a to b with hemispherical caps, of radius r and
 * strength s, whose field is s (1 - d^2/r^2)^2 within r of its centre or axis
 * (d the distance); the surface is where the fields add up to threshold.
 * A component's own transformations (src/eval_blob.c) that keep distances'
 * ratios are folded into a, b and r; any other (a non-uniform scale: POV-Ray's
 * ellipsoidal and stretched components) leaves a, b and r in the component's
 * own space, where its field is taken at inv(x). A component's own texture is
 * in the pool, placed in the blob's space; the others show the blob's.
 * Shared by every copy. */
typedef struct {
	double a[3], b[3], r, s;
	bool xformed;        /* xf and inv hold: the field is the component's own at inv(x) */
	xform xf, inv;       /* the component's own space to the blob's, and back */
	int texture;         /* 1 + its own texture in scene.textures, 0: the blob's */
} scene_blob_part;
typedef struct {
	double threshold;
	scene_blob_part *part;
	int n_parts;
} scene_blob;

/* The edges of a polygon, prism or text in their plane (src/prism.h), each
 * oriented so that the shape's inside is on its left: (x0, z0) to (x1, z1).
 * A text's glyphs are even-odd areas of their own, united: glyph g's edges
 * are glyph[g] to glyph[g + 1] - 1 (glyph NULL: one). Shared by every copy. */
typedef struct {
	double (*edge)[4];
	int n_edges;
	int *glyph;          /* n_glyphs + 1 entries, or NULL */
	int n_glyphs;
} scene_outline;

typedef struct {
	double location[3], direction[3], right[3], up[3];  /* final, after look_at */
	/* focal blur: off when aperture is 0 */
	double aperture;
	/* POV-Ray's focal distance: |focal_point - location| before the camera's
	 * transformations; without focal_point, |direction| after angle and look_at
	 * (1 without either); 0 becomes 1 */
	double focal_distance;
	double focal_point[3];
	int blur_samples;
	/* the whitted integrator's focal blur stops after blur_samples_min samples
	 * (0: after the first batch) once their variance is under variance, scaled
	 * for a confidence level (POV-Ray's defaults 0.9 and 1/10000) */
	int blur_samples_min;
	double confidence, variance;
	src_loc loc;
	int type;               /* CAMERA_ (kernels/shared.h) */
	/* POV-Ray's angle in degrees, which the types other than perspective and
	 * orthographic keep (default 90); the spherical camera's are h_angle
	 * and v_angle (default 360 and 180) */
	double angle, h_angle, v_angle;
	/* mesh_camera (CAMERA_MESH): its meshes are scene.camera_meshes[mesh_first ..
	 * mesh_first + mesh_count - 1]; rays per pixel, POV-Ray's distribution method
	 * 0 to 3, its maximum ray distance (0: none) and smooth */
	int mesh_first, mesh_count, mesh_rays, mesh_method;
	double mesh_max_distance;
	bool mesh_smooth;
	int normal;             /* normal { }: its pattern (scene.pigments), which perturbs each ray's
	                         * direction at POV-Ray's image point of the ray, or -1: none */
} scene_camera;

/* A mesh of a mesh_camera: scene.meshes[mesh] placed by xf. */
typedef struct {
	int mesh;
	xform xf;
} scene_camera_mesh;

typedef enum { LIGHT_POINT, LIGHT_SPOT, LIGHT_PARALLEL } scene_light_kind;

typedef struct {
	scene_light_kind kind;
	double position[3];
	float color[3];
	double point_at[3];          /* spotlight and parallel: default <0,0,1> */
	float radius, falloff, tightness; /* spotlight, degrees: 30, 45, 0 */
	/* area_light <axis1>, <axis2>, size1, size2: a rectangle of size1 x size2 lights */
	bool area;
	double axis1[3], axis2[3];
	int size1, size2, adaptive;   /* adaptive: 100 when not given, as in POV-Ray */
	bool jitter, circular, orient;
	bool shadowless;
	bool media_attenuation;      /* fogs dim its light on the way (POV-Ray's, default off) */
	bool no_media_interaction;   /* media_interaction off: media do not scatter its light */
	float fade_distance, fade_power; /* 0, 0: no falloff, as in POV-Ray */
	int looks_like;              /* first object index of its looks_like shape, or -1 */
	src_loc loc;
} scene_light;
/* POV-Ray's fog { }: type 1, constant, or 2, ground fog (fog_offset, fog_alt
 * along up), over distance; colour rgb, filter, transmit; turbulence (when
 * has_turb: any of turbulence, octaves, omega, lambda was written) scales the
 * distance a ray goes through it. Transformations only turn up. */
enum { SCENE_FOG_CONSTANT = 1, SCENE_FOG_GROUND = 2 };
typedef struct {
	int type;                /* SCENE_FOG_, 1 */
	double distance;         /* 0: no fog (POV-Ray skips it) */
	float colour[5];         /* black */
	double offset, alt;      /* 0, 0 */
	double up[3];            /* <0, 1, 0>, unit length */
	bool has_turb;
	double turbulence[3];    /* 0 */
	int octaves;             /* 6 */
	double omega, lambda;    /* 0.5, 2 */
	double turb_depth;       /* 0.5 */
	src_loc loc;
} scene_fog;

/* POV-Ray's rainbow { } as its Parse_Rainbow leaves it (src/eval_rainbow.c):
 * direction (the antisolar vector), up and right of unit length and at
 * right angles; angle is the inner edge (angle - width / 2) and width the
 * band's, in radians; arc_angle and falloff_angle are half the angles
 * written, in radians, or POV-Ray's default 180 (radians, so every ray is
 * within the arc). pigment: a gradient x pigment of the pool with the
 * colour_map, or -1 (no colour_map: POV-Ray skips the rainbow). */
typedef struct {
	double direction[3], up[3], right[3];
	double angle, width;     /* 0, 0 */
	double distance;         /* POV-Ray's MAX_DISTANCE, 1e7 */
	double jitter;           /* 0 */
	double arc_angle, falloff_angle;  /* 180, 180 */
	int pigment;
	src_loc loc;
} scene_rainbow;

/* A media { } (eval_media.c), POV-Ray 3.7's Parse_Media defaults
 * (scene_default_media). An interior's media are a chain through prev, the
 * last written first, never changed once made: materials copied by value
 * share them, and the chain's head names the interior's media. */
#define SCENE_MEDIA_DENSITIES 4
enum { SCENE_SCATTER_ISOTROPIC = 1, SCENE_SCATTER_MIE_HAZY, SCENE_SCATTER_MIE_MURKY, SCENE_SCATTER_RAYLEIGH,
       SCENE_SCATTER_HG };
typedef struct {
	double absorption[3], emission[3], scattering[3];   /* 0 */
	int type;                /* SCENE_SCATTER_, 1 */
	double eccentricity;     /* 0: Henyey-Greenstein's g */
	double extinction;       /* 1: scattering's share of the extinction */
	int method;              /* 3 */
	int intervals;           /* 1 */
	int min_samples, max_samples;  /* 10, 10 */
	double confidence, variance, ratio, jitter, aa_threshold;  /* 0.9, 1/128, 0.9, 0, 0.1 */
	int aa_level;            /* 3 */
	/* density { }s, multiplied: each a pattern (scene.pigments) or -1, a constant colour */
	int density[SCENE_MEDIA_DENSITIES];
	float density_rgb[SCENE_MEDIA_DENSITIES][3];
	int n_density;
	xform xf;                /* the media's transformations: they move its densities */
	int prev;                /* the media written before it in the same interior, or -1 */
	src_loc loc;
} scene_media;

/* A CSG object (union inside CSG, merge, intersection, difference, inverse):
 * its leaves are consecutive scene objects, and its program (kernels/shared.h,
 * CSG_; operands of CSG_LEAF are 0 .. n_leaves - 1) says how their insides
 * combine (src/csg.c). */
typedef struct {
	int first, n_leaves;
	int *ops;
	int n_ops;
	bool pattern;        /* an object pattern's object (params[0][0] of its pigment): only
	                      * its inside is asked, and it is never seen (no ray meets it) */
	src_loc loc;
} scene_csg;

/* A POV-Ray function { } as a closed program (src/eval_function.c): its
 * parameters are p0 .. n_params - 1, every declared value it named is a
 * constant, and a function it calls is an earlier one of the pool. The ops are
 * postfix: each pops its operands and pushes its result; the last leaves the
 * function's value. Lowering writes each function as OpenCL C from these ops
 * alone (src/lower_function.c), so nothing the scene wrote, no name and no
 * text, reaches the kernels' source; scene_function_eval runs the same program
 * on the host in double. */
#define SCENE_FOPS(X) \
	X(CONST, 0)  X(PARAM, 0)  X(CALL, 0) \
	X(NEG, 1)    X(NOT, 1)    X(ABS, 1)   X(ACOS, 1)  X(ASIN, 1)  X(ATAN, 1) \
	X(ACOSH, 1)  X(ASINH, 1)  X(ATANH, 1) X(CEIL, 1)  X(COS, 1)   X(COSH, 1) \
	X(DEGREES, 1) X(EXP, 1)   X(FLOOR, 1) X(INT, 1)   X(LN, 1)    X(LOG, 1) \
	X(RADIANS, 1) X(SIN, 1)   X(SINH, 1)  X(SQRT, 1)  X(TAN, 1)   X(TANH, 1) \
	X(ADD, 2)    X(SUB, 2)    X(MUL, 2)   X(DIV, 2)   X(LT, 2)    X(LE, 2) \
	X(GT, 2)     X(GE, 2)     X(EQ, 2)    X(NE, 2)    X(AND, 2)   X(OR, 2) \
	X(MIN, 2)    X(MAX, 2)    X(ATAN2, 2) X(POW, 2)   X(MOD, 2)   X(IDIV, 2) \
	X(COND, 3)   X(SELECT3, 3) X(SELECT4, 4) X(NOISE3, 3) \
	X(PATTERN, 3) X(PIGMENT, 3) \
	X(NOISE4, 4) X(HETERO_MF, 9) X(RIDGE, 9) X(RIDGED_MF, 9) X(POLYTUBES, 9)
enum {
#define X(name, arity) FOP_##name,
	SCENE_FOPS(X)
#undef X
	FOP_COUNT
};
/* CONST pushes value; PARAM pushes parameter arg; CALL pops the callee's
 * parameters (the last on top) and pushes function arg's value for them;
 * NOISE3 pops x, y, z and pushes POV-Ray's Noise there with noise_generator
 * arg, or the scene's when arg is 0 (f_noise3d). PATTERN pops x, y, z and
 * pushes the value there of pattern pigment arg (scene.pigments: POV-Ray's
 * f_pattern, its map unused); PIGMENT the same pigment's channel value (0
 * red, 1 green, 2 blue, 3 filter, 4 transmit, 5 grey: f_pigment). Only the
 * device runs these two: the host has no pattern evaluator, and evaluation
 * keeps them out of what the host runs. The last five are POV-Ray's internal
 * functions that loop (internal(78, 29, 58, 59, 52)), on x, y, z and then
 * their parameters as functions.inc lists them: NOISE4 f_noise_generator,
 * HETERO_MF f_hetero_mf, RIDGE f_ridge, RIDGED_MF f_ridged_mf (their noise
 * generator a parameter), POLYTUBES f_polytubes. */
#define SCENE_FOP_ARITY_MAX 9
typedef struct {
	int op, arg;
	double value;
} scene_fop;
typedef struct {
	int n_params;
	scene_fop *ops;
	int n_ops;
	src_loc loc;
	const void *key;         /* what it was made from: eval makes a function once */
} scene_function;
/* The most a program may push, and the most ops in all a scene's functions may
 * have (eval_function.c refuses more): a kernel must stay small enough to build. */
#define SCENE_FUNCTION_STACK 64
#define SCENE_MAX_FOPS 200000

typedef struct {
	scene_camera camera;
	scene_object *objects;
	int n_objects, cap_objects;
	scene_light *lights;
	int n_lights, cap_lights;
	scene_mesh *meshes;
	int n_meshes, cap_meshes;
	scene_csg *csgs;
	int n_csgs, cap_csgs;
	scene_function *functions;  /* the functions patterns and shapes run on the device */
	int n_functions, cap_functions, n_fops;
	scene_outline *outlines;
	int n_outlines, cap_outlines;
	scene_blob *blobs;
	int n_blobs, cap_blobs;
	scene_camera_mesh *camera_meshes;  /* the mesh_cameras' meshes (scene_camera.mesh_first) */
	int n_camera_meshes, cap_camera_meshes;
	scene_poly *polys;
	int n_polys, cap_polys;
	scene_pigment *pigments;   /* the pattern pigments' pool, scene_material.pattern */
	int n_pigments, cap_pigments;
	scene_material *textures;  /* the pool of textures that texture_maps and layers hold
	                            * (scene_material.texture_map, layers, below), never changed once made */
	int n_textures, cap_textures;
	scene_image *images;       /* the image_maps' images, params[0][0] of their pigments */
	int n_images, cap_images;
	float background[3];
	/* The background's filter and transmit, which only an alpha channel (+UA)
	 * sees: POV-Ray 3.7's default background is <0,0,0,0,1>, transparent;
	 * a #version below 3.7 makes any background so. */
	float background_ft[2];
	float sky[3];         /* sky_sphere's colour (its top pigment's average); used when has_sky */
	bool has_sky;
	scene_material *sky_layers;  /* the sky_sphere's pigments as written (the last on top),
	                              * its transformations in tex_xf, its emission in emission */
	int n_sky_layers;
	bool uv_mapped;       /* some texture is uv_mapped: a rotated sphere keeps its rotation */
	bool sky_legacy;      /* the scene's #version is before 3.7: the sky_sphere's layers
	                       * blend as POV-Ray 3.6 blends them */
	scene_fog *fogs;      /* in the order written; they combine as POV-Ray combines them */
	int n_fogs, cap_fogs;
	scene_rainbow *rainbows;   /* in the order written; they blend as POV-Ray blends them */
	int n_rainbows, cap_rainbows;
	scene_media *media;   /* every interior's media (scene_material.media) and the atmosphere's */
	int n_media, cap_media;
	int atmosphere;       /* the scene-level media's chain head plus one; 0: none */
	/* global_settings */
	int max_trace_level;  /* 0 when the scene does not say */
	float assumed_gamma;  /* 0 when the scene does not say */
	float film_gamma;     /* the film's colours to linear ones: c ^ film_gamma, POV-Ray's
	                       * working gamma (assumed_gamma, else 1); 0 when POV-Ray turns
	                       * gamma correction off (an older #version without assumed_gamma):
	                       * the colours are written into 8-bit images as they are */
	float adc_bailout;    /* 1/255 */
	int noise_generator;  /* a pattern's without one of its own: 1, 2 or 3, POV-Ray's 2 */
	int number_of_waves;  /* the wave sources of every waves and ripples: POV-Ray's 10 */
	float ambient_light[3]; /* 1 */
	float irid_wavelength[3]; /* 0.70, 0.52, 0.48: POV-Ray 3.7's (its manual says otherwise) */
} scene;

void scene_init(scene *s);
/* The noise generator pg uses: its own, else the scene's. */
int scene_noise_generator(const scene *s, const scene_pigment *pg);
/* Appends; exits with a message on out of memory. */
void scene_add_object(scene *s, const scene_object *o);
void scene_add_light(scene *s, const scene_light *l);
void scene_add_fog(scene *s, const scene_fog *f);
/* POV-Ray's default fog (Create_Fog): no distance, so no fog until one is given. */
scene_fog scene_default_fog(void);
void scene_add_rainbow(scene *s, const scene_rainbow *r);
/* Appends a media to the pool; returns its index. */
int scene_add_media(scene *s, const scene_media *m);
/* POV-Ray 3.7's media defaults (method 3, one interval, 10 samples). */
scene_media scene_default_media(void);
/* Takes ownership of p's map; returns its index. */
int scene_add_pigment(scene *s, const scene_pigment *p);
/* A texture into the pool scene.textures; returns its index. */
int scene_add_texture(scene *s, const scene_material *m);
/* Takes ownership of im's key and pixels; returns its index. */
int scene_add_image(scene *s, const scene_image *im);
/* Takes ownership of m's arrays; returns its index. */
int scene_add_mesh(scene *s, scene_mesh *m);
/* Takes ownership of c's ops; returns its index. */
int scene_add_csg(scene *s, const scene_csg *c);
/* Takes ownership of f's ops; returns its index. */
int scene_add_function(scene *s, const scene_function *f);
/* The value of function f for its parameters' values args, as the device computes it
 * but in double: the host's twin of the OpenCL that lowering writes. */
double scene_function_eval(const scene *s, int f, const double *args);
/* The values of a pattern or pigment function's pigment at n points p (three
 * doubles a point) for scene_function_eval_many: its pattern's value (colour
 * false: out[5 * i]) or its colour (out[5 * i ...]: red, green, blue, filter,
 * transmit). 0, or -1 after saying why. */
typedef int (*scene_pattern_points)(void *ctx, int pigment, bool colour, int n, const double *p, double *out);
/* scene_function_eval at n points at once (args: n_params doubles a point),
 * the same ops in the same order, so the same values, and the pattern and
 * pigment ops through pattern (NULL: they are 0, as in scene_function_eval),
 * one call for all n points. 0, or -1 when pattern failed or memory ran out. */
int scene_function_eval_many(const scene *s, int f, int n, const double *args, double *out,
                             scene_pattern_points pattern, void *ctx);
/* The levels of functions a call of function f runs on the device: 1 when
 * the patterns its pattern and pigment ops read (its callees' too) are no
 * function patterns, 2 when they run functions of level 1, and so on; the
 * kernels make a copy of the functions for each level (OpenCL C has no
 * recursion). A pigment's: the deepest level of the function patterns in its
 * tree, 0 without any. A cycle, which eval cannot make, counts as too deep. */
#define SCENE_FUNCTION_LEVELS_MAX 4
int scene_function_levels(const scene *s, int f);
int scene_pigment_levels(const scene *s, int pigment);
/* Whether function f, or one it calls, calls a pattern or pigment function,
 * which only the device evaluates (scene_function_eval cannot). */
bool scene_function_calls_patterns(const scene *s, int f);
/* POV-Ray's Noise at p, in [0, 1], with noise_generator 1, 2 or 3, as
 * kernels/pattern.cl's pattern_noise computes it, in float (scene_noise.c). */
float scene_noise(const float p[3], int generator);
/* The value of a noise op of the functions (FOP_NOISE4, FOP_HETERO_MF,
 * FOP_RIDGE, FOP_RIDGED_MF) on its operands a, as kernels/pattern.cl's
 * function_noise4 ... function_ridged_mf compute it (scene_noise.c). */
double scene_noise_op(int op, const double *a);
/* POV-Ray's DTurbulence at p, as kernels/pattern.cl's pattern_dturbulence
 * computes it (scene_noise.c): vturbulence(). */
void scene_dturbulence(const float p[3], float omega, float lambda, int octaves, float out[3]);
/* An FOP_ of arithmetic, or of the noise functions and f_polytubes, on its
 * operands a[0 .. arity - 1] (not CONST, PARAM, CALL, NOISE3, PATTERN,
 * PIGMENT, which need more than their operands), as the host runs it. */
double scene_fop_apply(int op, const double *a);
/* An FOP_'s operand count and name ("add"). */
int scene_fop_arity(int op);
const char *scene_fop_name(int op);
/* Takes ownership of o's arrays; returns its index. */
int scene_add_outline(scene *s, const scene_outline *o);
/* Takes ownership of p's coefficients; returns its index. */
int scene_add_poly(scene *s, const scene_poly *p);
/* Takes ownership of b's parts; returns its index. */
int scene_add_blob(scene *s, const scene_blob *b);
/* Appends a mesh_camera's mesh; returns its index. */
int scene_add_camera_mesh(scene *s, const scene_camera_mesh *m);
void scene_free(scene *s);
/* Frees a mesh's arrays (those of a mesh not added to a scene: scene_free frees
 * the scene's own). */
void scene_mesh_free(scene_mesh *m);
/* Grows [lo, hi] by the object's box in world space (planes reach 1e10, as in
 * POV-Ray); start with lo = +huge and hi = -huge. */
void scene_object_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3]);
/* A PATTERN_'s name (kernels/shared.h): "checker". */
const char *scene_pattern_name(int kind);
/* Writes the scene in world space, one entity a line, for --dump-scene and golden tests. */
void scene_dump(const scene *s, FILE *out);
scene_material scene_default_material(void);
/* POV-Ray's default light_source fields: a point light. */
scene_light scene_default_light(void);
/* POV-Ray's default camera: at the origin looking along +z, 4:3. */
scene_camera scene_default_camera(void);
/* POV-Ray 3.7's look_at: points direction at p keeping the lengths of direction,
 * right and up, orients right and up by sky, keeps the handedness of right.
 * Returns -1 when p is the camera's location, 1 when the view is along sky
 * (right is then kept, as POV-Ray does), else 0. */
int scene_camera_look_at(scene_camera *c, const double p[3], const double sky[3]);
/* A camera type's words in a scene ("fisheye", "cylinder 1"). */
const char *scene_camera_name(int type);

#endif
