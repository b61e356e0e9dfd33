/* eval_int.h: what the files of the evaluation stage (eval*.c) share: values,
 * the symbol scopes, and the cursor that walks a block's items and runs the
 * directives among them. Not for other stages: they see eval.h only. */
#ifndef ECLAT_EVAL_INT_H
#define ECLAT_EVAL_INT_H

#include <stdbool.h>

#include "eval.h"

typedef enum { /* ORDER: eval_kind_name */
	V_NONE,      /* an array element not set yet */
	V_FLOAT, V_VECTOR, V_COLOR, V_STRING,
	V_OBJECT, V_PIGMENT, V_FINISH, V_TEXTURE, V_NORMAL, V_INTERIOR, V_MATERIAL,
	V_COLOR_MAP, V_TRANSFORM, V_CAMERA, V_ARRAY, V_MACRO, V_FUNCTION, V_SPLINE, V_FOG, V_MEDIA, V_OTHER,
} val_kind;

/* A light and the looks_like objects that go with it. */
struct lightval {
	scene_light light;
	scene_object *looks;
	int n_looks;
};

/* An object value: the shapes it is made of (a union has several) and the lights
 * in it. A union's own texture is kept apart (has_mat, mat) and given to its
 * parts without one when the union is used, as POV-Ray does. */
/* A CSG object among an object value's shapes: its leaves objs[first ..
 * first + n_leaves - 1], and its program (csg.h) over them. */
struct objcsg {
	int first, n_leaves;
	int *ops;
	int n_ops;
	src_loc loc;
};

struct objval {
	scene_object *objs;
	int n_objs, cap_objs;    /* cap_objs: the room objs has (eval_objval_add grows it by halves) */
	struct objcsg *csgs;     /* the CSG objects among objs; the others stand alone */
	int n_csgs;
	struct objval *bound;    /* bounded_by's objects, for clipped_by { bounded_by }, or NULL */
	struct lightval *lights;
	int n_lights;
	bool compound;
	bool has_mat;            /* mat's texture is the compound's own */
	bool has_interior;       /* mat's interior is the compound's own */
	scene_material mat;
	bool uv;                  /* uv_mapping written (before the texture): its textures are uv_mapped */
	const char *unsupported;  /* a POV-Ray object eclat cannot render: its name */
	src_loc unsupported_loc;
	src_loc loc;
};

struct array;

/* A value of the language. Pigments, finishes, textures, interiors and materials
 * share scene_material: a pigment uses its pigment part, a finish the finish
 * part, a texture both, an interior the interior part. */
typedef struct value {
	val_kind kind;
	int n;                   /* components of a vector (2 to 5); colours have 5 */
	double v[5];             /* a float is v[0] */
	char *str;               /* V_STRING; V_OTHER: what it is ("fog") */
	struct objval *obj;      /* V_OBJECT */
	scene_material mat;      /* V_PIGMENT ... V_MATERIAL, V_COLOR_MAP (its average in pigment) */
	xform xf;                /* V_TRANSFORM */
	scene_camera *cam;       /* V_CAMERA */
	scene_fog *fog;          /* V_FOG */
	int media;               /* V_MEDIA: its index in scene.media */
	struct array *arr;       /* V_ARRAY */
	const ast_node *node;    /* V_MACRO, V_FUNCTION: the definition (a pattern or pigment
	                          * function's pigment in mat) */
	struct scope *env;       /* V_FUNCTION: the names it uses from the macro or include it
	                          * was made in (eval_capture), or NULL */
} value;

struct array {
	int dims, size[5];
	int n;                   /* product of the sizes */
	value *elems;
};

/* ---- values (eval_value.c) ---- */
const char *eval_kind_name(val_kind k);  /* "a float" */
void eval_value_free(value *v);
value eval_value_copy(const value *v);
value eval_float(double f);
value eval_vector3(const double v[3]);
bool eval_is_numeric(val_kind k);
/* Promotes a float or vector to n components: a float fills them all, the
 * components a vector does not have are 0. */
void eval_widen(const value *v, int n, double out[5]);
struct objval *eval_objval_new(src_loc loc);
void eval_objval_add(struct objval *o, const scene_object *so);
void eval_objval_add_light(struct objval *o, const struct lightval *l);
/* Appends src's parts to dst (src keeps its own). */
void eval_objval_merge(struct objval *dst, const struct objval *src);
void eval_objval_free(struct objval *o);
void *eval_xrealloc(void *p, size_t size);
char *eval_xstrdup(const char *s);

/* ---- the evaluator ---- */
struct symbol;
struct scope;
struct cursor;

/* What an error inside an #include or a macro call was reached through. */
struct context {
	const char *macro;       /* NULL for an include */
	src_loc from;
};

#define EVAL_MAX_CONTEXT 300
#define EVAL_MAX_ERRORS 20

struct rng {
	unsigned *state;
	int n;
};

struct eval {
	scene *s;
	const eval_options *opt;
	struct scope *scope;     /* innermost; ->parent toward the global one */
	struct scope *global;
	struct context ctx[EVAL_MAX_CONTEXT];
	int n_ctx;
	int macro_depth, include_depth;
	bool stop;               /* #error, or too many errors: evaluate nothing more */
	src_loc last_error;      /* a second error there stops too (a loop repeating it) */
	int errors_at_start;
	scene_material default_mat;  /* #default */
	double version;
	bool version_given;      /* a #version ran */
	src_loc version_loc;     /* where the last #version ran */
	bool noise_given;        /* global_settings gave a noise_generator */
	struct rng rng;
	ast_node **trees;        /* included files, kept while their macros may run */
	int n_trees;
	char **warned;           /* the constructs already warned about, with their place */
	int n_warned;
	int deferring;           /* inside a declaration of an include file: warnings wait */
	struct eval_warning *pending;  /* the warnings waiting, for the declaration's symbol */
	int n_pending;
	struct eval_file *files; /* #fopen's open files (eval_fileio.c) */
	int n_files;
	struct eval_access *access;  /* the folders the scene may read and write (eval_access.c) */
	double memory_used, memory_limit;  /* bytes (eval_memory.c); limit 0: not looked up yet */
	struct eval_font *fonts; /* the texts' outlines already read (eval_outline.c) */
	int n_fonts;
	struct scope **envs;     /* the functions' captured names (eval_capture), freed at the end */
	int n_envs;
};

/* A function made inside a macro or an include file sees that scope's
 * parameters and #locals, as POV-Ray compiles it there; eclat compiles or
 * evaluates it when it is used, so the values of the names its body uses
 * that are not global are kept, and put back in sight around that use.
 * eval_capture: them (NULL when there are none); eval_env_push: 1 when it
 * pushed env, which eval_env_pop then takes away. */
struct scope *eval_capture(struct eval *e, const ast_node *def);
int eval_env_push(struct eval *e, struct scope *env);
void eval_env_pop(struct eval *e, int pushed);

/* The working gamma as far as the scene has been read (scene.film_gamma,
 * which eval sets at the end): assumed_gamma, else 1, or 0 (gamma correction
 * off) under a #version older than 3.7. */
double eval_working_gamma(const struct eval *e);

/* Frees the texts' outline cache (not the outlines: the scene has them). */
void eval_outline_free(struct eval *e);

/* Memory for what the scene loads (eval_memory.c): claim bytes before
 * allocating them; -1 after an error at loc that names what and the numbers.
 * eval_memory_left: the bytes still free to claim. */
int eval_memory_claim(struct eval *e, src_loc loc, double bytes, const char *what);
double eval_memory_left(struct eval *e);

/* Errors and warnings with the chain of includes and macro calls as notes. */
void eval_error(struct eval *e, src_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void eval_warning(struct eval *e, src_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A warning inside a declaration of an include file waits in the declared
 * identifier until the scene uses it: textures.inc's unused textures say
 * nothing. */
struct eval_warning {
	src_loc loc;
	char *msg;
};
/* The identifier name is used at loc: its waiting warnings are printed, once,
 * with a note that points there. */
void eval_used(struct eval *e, const char *name, src_loc loc);
/* A warning printed once per key and place ("pattern marble" at 3:12): a
 * construct in a loop or a macro warns once, and each place that uses it does. */
void eval_warn_once(struct eval *e, src_loc loc, const char *key, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

/* Symbols. lookup follows POV-Ray's dynamic scoping: the innermost scope first,
 * out to the global one. */
value *eval_lookup(struct eval *e, const char *name);
/* #declare (local false) or #local (local true) NAME = v; takes v. */
void eval_assign(struct eval *e, const char *name, value v, bool local);
bool eval_undef(struct eval *e, const char *name);
void eval_suggest(struct eval *e, const char *name, char *out, size_t size);

/* ---- the cursor (eval.c): the items of a block, directives run ---- */
struct frame;
struct cursor {
	struct frame *frames;
	int n, cap;
	const ast_node *pending;   /* an item given back by eval_unget */
	struct eval *e;
	bool lenient;              /* the top level: an error in a directive does not end it */
};

void eval_cursor_init(struct cursor *c, struct eval *e, const ast_node *block);
void eval_cursor_free(struct cursor *c);
/* The next item that is not a directive, after running those before it; NULL at
 * the end of the block or after an error (then *err is set). An item must be
 * evaluated before the next call: a macro's scope ends when its body does. */
const ast_node *eval_next(struct cursor *c, int *err);
void eval_unget(struct cursor *c, const ast_node *item);
/* The next item if it is an expression (used for optional arguments), else NULL
 * with the item left for the next eval_next. */
const ast_node *eval_next_expr(struct cursor *c, int *err);
/* The same for an optional value after a keyword (hollow [Bool]): an
 * identifier that is not declared is no value but the next keyword of POV-Ray's. */
const ast_node *eval_next_optional(struct cursor *c, int *err);

/* Whether a file named in the scene can be found, as #include looks for it. */
bool eval_file_exists(struct eval *e, int from_file, const char *name);
/* Its path (to free), or NULL when it cannot be found. */
char *eval_find_file(struct eval *e, int from_file, const char *name);

/* The include folder of the installed eclat (eval_path.c): PKGDATADIR/include,
 * found from where the binary runs; NULL when there is none. */
const char *eval_installed_include_dir(void);

#define EVAL_POV_INCLUDE_DIR "/usr/share/povray-3.7/include"

/* ---- file I/O security (eval_access.c) ---- */
/* The folders the scene whose file is scene_file may read and write, from
 * e->opt; eval_access_free lets them go. */
void eval_access_init(struct eval *e, int scene_file);
void eval_access_free(struct eval *e);
/* 0 when the scene may open path (as eclat would open it: relative to the
 * current folder) for reading, or for writing when write is set; else -1 after
 * an error at loc that starts with what ("#include") and names the resolved
 * path and the option that would allow it. */
int eval_access(struct eval *e, const char *path, bool write, src_loc loc, const char *what);
/* The same without a message: for file_exists and hints. */
bool eval_access_allowed(struct eval *e, const char *path, bool write);

/* spline { ... } and calls of a spline (eval_spline.c) */
int eval_spline_value(struct eval *e, const ast_node *b, value *out);
int eval_spline_call(struct eval *e, const ast_node *call, const value *spl, value *out);

/* trace(OBJECT, <Start>, <Direction> [, NORMAL]) (eval_trace.c) */
int eval_trace(struct eval *e, const ast_node *call, value *out);
/* inside(OBJECT, <Point>): 1 or 0 (eval_trace.c) */
int eval_inside(struct eval *e, const ast_node *call, value *out);

/* The arguments of a shape whose class has no args string (polygon, prism,
 * text: eval_outline.c), into o; -1 after an error. */
int eval_outline_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* poly, cubic, quartic and polynomial (eval_poly.c) */
int eval_poly_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* A placed poly's bounded_by (eval_poly.c). */
void eval_poly_bound(struct eval *e, scene_object *o, const struct objval *bound);

/* ---- patterns (eval_pattern.c) ---- */
/* The PATTERN_ of a pattern's name, or -1. */
int eval_pattern_kind(const char *name);
int eval_pattern_list_size(int kind);
void eval_pattern_defaults(scene_pigment *pg, int kind, src_loc loc);
/* Gives pg POV-Ray's default colours or colour map. */
void eval_pattern_default_map(scene_pigment *pg);
/* A pattern modifier (turbulence, warp, brick_size...): 0 when item was one and
 * went into pg, 1 when it is not one, -1 after an error. */
int eval_pattern_modifier(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg);
/* A transformation written in a pigment with a pattern, into its warps' list. */
int eval_pattern_transform(struct eval *e, scene_pigment *pg, const xform *t, src_loc loc);
/* A new pattern in a pigment that had one (old, or NULL), t the texture's
 * transformations since: old's warps and t go to the back of pg's list. */
int eval_pattern_continue(struct eval *e, scene_pigment *pg, const scene_pigment *old, const xform *t,
                          src_loc loc);
/* The argument of a pattern keyword: gradient's vector, spiral's arms. */
int eval_pattern_argument(struct eval *e, const ast_node *item, scene_pigment *pg);
/* A pavement's numbers checked and reduced as POV-Ray does; 0 for other patterns. */
int eval_pavement_check(struct eval *e, scene_pigment *pg, src_loc loc);
/* tiling N: its number, read after the keyword (eval_pattern.c). */
int eval_pattern_tiling(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg);
/* mandel, julia and magnet (eval_fractal.c): their defaults, and their
 * arguments and modifiers, as eval_pattern_modifier. */
bool eval_pattern_is_fractal(int kind);
void eval_fractal_defaults(scene_pigment *pg);
int eval_fractal_modifier(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg);
/* julia_fractal { }'s words before its object modifiers (eval_fractal.c). */
int eval_julia_fractal_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);

/* The slope pattern's word at item (slope { ... }, slope V, or slope -V,
 * which the grammar makes one difference), or NULL. */
const ast_node *eval_slope_word(struct eval *e, const ast_node *item);
/* Its arguments into pg (a slope pattern): 0, -1 after an error, 2 for a
 * form eclat does not have (point_at), warned about. */
int eval_pattern_slope(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg);


/* image_map { ... }: pg (an image_map pattern) gets its image, read into the
 * scene's images once per file and gamma, its options and a one-entry map of
 * its average colour. -1 after an error. */
int eval_image_map(struct eval *e, const ast_node *b, scene_pigment *pg);
int eval_image_pattern(struct eval *e, const ast_node *b, scene_pigment *pg);
int eval_bump_map(struct eval *e, const ast_node *b, scene_pigment *pg);
/* material_map { IMAGE... TEXTURE... }: the image into pg; texture is called
 * with ctx for each item that is no image item (0: taken, 1: not valid, -1:
 * an error reported). */
int eval_material_map(struct eval *e, const ast_node *b, scene_pigment *pg,
                      int (*texture)(struct eval *, const ast_node *, void *), void *ctx);
/* density_file df3 "File" (eval_df3.c), item the word density_file: reads df3
 * and the name from c, the file into the scene's images, and pg's params.
 * interpolate N's argument arg into a density_file's pg. -1 after an error. */
int eval_density_file(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg);
int eval_density_file_interpolate(struct eval *e, const ast_node *arg, scene_pigment *pg);

/* ---- #fopen, #read, #write, #fclose (eval_fileio.c) ---- */
void eval_file_io(struct eval *e, const ast_node *d);
void eval_files_close(struct eval *e);

/* A macro call in a value position: the one value its body produces. */
int eval_macro_value(struct eval *e, const ast_node *call, const value *macro, value *out);

int eval_if_value(struct eval *e, const ast_node *n, value *out);

/* ---- expressions (eval_expr.c) ---- */
int eval_expr(struct eval *e, const ast_node *n, value *out);
/* Sets the component of n (red F...) in base (taken). */
int eval_component(struct eval *e, const ast_node *n, value *base, value *out);
int eval_expect_float(struct eval *e, const ast_node *n, double *f);
int eval_expect_int(struct eval *e, const ast_node *n, int *i);
/* (int)f as POV-Ray gets it on x86: NaN and values out of int's range give INT_MIN
 * (a plain C cast is undefined there). Every float a scene gives that becomes an
 * int goes through this or a range check first. */
int eval_int_of(double f);
int eval_expect_vector(struct eval *e, const ast_node *n, double out[3]);
int eval_expect_color(struct eval *e, const ast_node *n, double out[5]);
int eval_expect_string(struct eval *e, const ast_node *n, char **out);
/* Evaluates n and checks its kind: "expected a finish, found a float". */
int eval_expect_kind(struct eval *e, const ast_node *n, val_kind kind, value *out);
/* The value a node refers to, without copying (an identifier, an element), or NULL. */
value *eval_reference(struct eval *e, const ast_node *n, int *err);
bool eval_is_defined(struct eval *e, const ast_node *n);
bool eval_truth(double f);
int eval_call_function(struct eval *e, const ast_node *call, const value *fn, value *out);
/* The device's program (scene.functions) for the function def (an AST_FUNCTION),
 * made once (eval_function.c). 0; -1 after an error; 1 when it uses what the
 * device cannot run and --skip-unsupported made that a warning, which ends
 * with instead ("the pattern is averaged"). */
int eval_function_index(struct eval *e, const ast_node *def, const char *instead, int *index);
/* The same for a pigment's function pattern, which may call pattern and pigment
 * functions (the device runs it with the scene's pattern buffers). */
int eval_function_pattern_index(struct eval *e, const ast_node *def, const char *instead, int *index);
/* The pattern { } or pigment { } that the function def is made of (a pattern
 * or pigment function), or NULL. */
const ast_node *eval_function_pattern_body(const ast_node *def);
/* That pattern or pigment evaluated, into out's pigment part (where it is
 * declared, as POV-Ray does: a macro's locals are still there). */
int eval_function_pigment(struct eval *e, const ast_node *def, scene_material *out);
/* The pool's pigment at n points p (three doubles a point) through
 * eval_options.pattern_at, which must be set, with the working gamma and noise
 * generator in effect so far: its pattern's value (colour false: out[5 * i])
 * or its colour (out[5 * i ...]). 0, or -1 after an error at loc. */
int eval_pattern_points(struct eval *e, src_loc loc, int pigment, bool colour, int n, const double *p, double *out);
/* pigment_pattern { PIGMENT } (block b) as a function pattern's program: the
 * grey of the pigment's colour at x, y, z (POV-Ray 3.7's pigment_pattern).
 * Returns as eval_function_index does. */
int eval_function_pigment_pattern(struct eval *e, const ast_node *b, const char *instead, int *index);
/* POV-Ray's internal function number (functions.inc's internal(N)) written in
 * POV-Ray's language, or NULL when eclat has not written it (eval_internal.c). */
const ast_node *eval_internal_function(int number);
/* internal(number)'s op, when it is one op on its parameters (f_noise3d, the
 * noise functions, f_polytubes), and its number of parameters; else -1. */
int eval_internal_op(int number, int *n_params);
/* What the error for another number says eclat has (eval_function.c's and
 * eval_expr.c's, for the device and the host). */
#define EVAL_INTERNAL_RANGE "0 to 78 but 77 (f_pattern, which functions.inc does not declare)"
/* A word of POV-Ray's that is no keyword of eclat's parser (threshold,
 * component...): its name, or NULL. "threshold -0.2" reaches the evaluator as
 * threshold - 0.2: then *negated is the number after it (eval_isosurface.c). */
const char *eval_word_item(const ast_node *n, const ast_node **negated);
/* The float after such a word at: minus *negated's value, or the next item's. */
int eval_word_float(struct eval *e, struct cursor *c, const ast_node *at, const ast_node *negated, double *f);
/* height_field { }'s own items: its mesh into o->mesh (eval_hfield.c). */
int eval_height_field_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* bicubic_patch { }'s own items: its triangles into o->mesh (eval_bicubic.c). */
int eval_bicubic_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* blob { }'s own items (eval_blob.c). */
int eval_blob_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* contained_by { box { } | sphere { } } of an isosurface or a parametric into
 * o: p[0], p[1] a box's corners (ordered), or p[0] and radius a sphere's
 * centre and radius with n[0][0] set (eval_isosurface.c). */
int eval_contained_by(struct eval *e, const ast_node *b, scene_object *o);
/* parametric { }'s own items: its triangles into o->mesh (eval_parametric.c). */
int eval_parametric_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* sphere_sweep { }'s own items (eval_sweep.c). */
int eval_sweep_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* isosurface { }'s own items, up to its object modifiers (eval_isosurface.c). */
int eval_isosurface_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o);
/* Evaluates a function's body with its parameters (names, or the definition's
 * when NULL) bound to args in a scope of their own. */
int eval_function_body(struct eval *e, const ast_node *def, const char *const *names, const double *args, int n,
                       value *out);

/* ---- blocks (eval_object.c, eval_material.c, eval_world.c) ---- */
/* The value of a block in a value position: #declare X = BLOCK, a macro's result. */
int eval_block_value(struct eval *e, const ast_node *b, value *out);
int eval_object(struct eval *e, const ast_node *b, value *out);
bool eval_is_object_block(const ast_node *b);
int eval_transform_item(struct eval *e, struct cursor *c, const ast_node *item, xform *t);
xform eval_xform_inverse(const xform *t);
int eval_material_block(struct eval *e, const ast_node *b, scene_material *m);
int eval_material_value(struct eval *e, const ast_node *b, value *out);
void eval_apply_value(const value *v, scene_material *m);
/* A texture given to an object: it replaces the object's (untextured) or is
 * layered on it (textured), as POV-Ray layers textures. */
void eval_apply_texture(struct eval *e, src_loc loc, scene_material *m, bool textured, const scene_material *tex);
int eval_looks_like(struct eval *e, const ast_node *b, const double at[3], struct lightval *l);
void eval_transform_light(struct lightval *l, const xform *t);
int eval_camera(struct eval *e, const ast_node *b, scene_camera *out);
/* mesh_camera { } in a camera (eval_camera_mesh.c): makes c a mesh camera */
int eval_camera_mesh(struct eval *e, const ast_node *b, scene_camera *c);
/* fog { } (eval_fog.c): as a statement, and as a value */
int eval_fog(struct eval *e, const ast_node *b, scene_fog *out);
int eval_fog_statement(struct eval *e, const ast_node *b);
int eval_fog_value(struct eval *e, const ast_node *b, value *out);
/* rainbow { } (eval_rainbow.c), a statement */
int eval_rainbow_statement(struct eval *e, const ast_node *b);
/* media { } (eval_media.c): in an interior (appended to m's media), at the
 * scene's level (the atmosphere), and as a value */
int eval_media_interior(struct eval *e, const ast_node *b, scene_material *m);
/* irid { } in a finish, and global_settings' irid_wavelength (eval_irid.c); the
 * latter returns 1 when item is something else. */
int eval_irid(struct eval *e, const ast_node *b, scene_material *m);
int eval_irid_wavelength(struct eval *e, struct cursor *c, const ast_node *item);
int eval_media_statement(struct eval *e, const ast_node *b);
int eval_media_value(struct eval *e, const ast_node *b, value *out);
/* A media's density { } (eval_material.c: it is read as a pigment). */
int eval_media_density(struct eval *e, const ast_node *b, scene_media *md);
int eval_density_value(struct eval *e, const ast_node *b, value *out);
int eval_light(struct eval *e, const ast_node *b, value *out);
int eval_scene_statement(struct eval *e, const ast_node *b);
int eval_default(struct eval *e, const ast_node *d);
void eval_place(struct eval *e, value *obj);
/* An object pattern's object, item, into the scene as a CSG no ray meets; its index. */
int eval_pattern_object(struct eval *e, const ast_node *item, int *csg);
/* Whether pigment's tree holds an object pattern, which no function runs (eval_function.c). */
bool eval_pigment_has_object(const scene *s, int pigment);
/* Complains about an item a block does not accept. */
int eval_not_valid(struct eval *e, const ast_node *item, const char *where);
int eval_skip_pov_word(struct eval *e, struct cursor *c, const ast_node *item);
const ast_node *eval_pov_word_item(struct eval *e, const ast_node *item);
/* The POV-Ray words eclat parses but cannot do: "object", "modifier"... or NULL. */
const char *eval_pov_word(const char *name);
/* Colours: pow(sRGB decode(c), 1 / assumed_gamma). */
double eval_srgb_decode(double c);

#endif
