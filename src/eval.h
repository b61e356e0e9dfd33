/* eval.h: evaluates a syntax tree (directives, expressions, #include) into a scene. */
#ifndef ECLAT_EVAL_H
#define ECLAT_EVAL_H

#include <stdbool.h>

#include "ast.h"
#include "scene.h"

/* POV-Ray's [File I/O Security] levels (--io-security); restricted, the
 * default, is 0 so that options set to zero are the safe ones. */
typedef enum {
	EVAL_IO_RESTRICTED,  /* reads and writes only in the folders allowed */
	EVAL_IO_READ_ONLY,   /* reads anywhere, writes only in the folders allowed */
	EVAL_IO_NONE,        /* no restriction but the file system's */
} eval_io_security;

/* What the command line tells the evaluator. Zero-initialise, or use
 * eval_options_default, then set what is given. */
typedef struct {
	/* -I DIR, --include-path DIR, in order. An #include "F" with a relative F is
	 * looked for in the including file's folder, then in these, then in the
	 * folders of $ECLAT_INCLUDE_PATH (separated by ':'), then in eclat's installed
	 * include folder (eval_path.c), then in /usr/share/povray-3.7/include when
	 * it exists. */
	const char *const *include_dirs;
	int n_include_dirs;
	/* -D NAME=VALUE and POV-Ray's Declare=NAME=VALUE: VALUE is a float, a quoted
	 * string or any expression. Each is declared, in order, before the scene is
	 * read, as by "#declare NAME = VALUE;". An error in one is reported against
	 * the text "NAME=VALUE". */
	const char *const *declares;
	int n_declares;
	/* An object eclat cannot render (cylinder, torus...) is left out with a
	 * warning instead of being an error. */
	bool skip_unsupported;
	/* image_width and image_height in the scene; 0 means 640 by 480. */
	int image_width, image_height;
	/* The animation's values for the frame (POV-Ray's clock, clock_delta,
	 * clock_on, frame_number, initial_ and final_clock and _frame); all 0 by
	 * default, as in POV-Ray without an animation. */
	double clock, clock_delta, initial_clock, final_clock;
	bool clock_on;
	long frame_number, initial_frame, final_frame;
	/* Limits that stop a runaway scene with a clear error instead of a hang or a
	 * crash (--max-include-depth, --max-macro-depth, --max-loop-iterations);
	 * 0 means the EVAL_DEFAULT_ value. */
	int max_include_depth, max_macro_depth;
	long max_loop_iterations;
	/* Seconds a library (assimp, OpenImageIO, libpng, FreeType) may take on one
	 * file (--load-time-limit, alias --mesh-time-limit); 0: no limit. */
	unsigned mesh_time_limit;
	/* Bytes the scene's images, meshes and height fields may take
	 * (--memory-limit); 0: what the host has available (eval_memory.c). */
	double memory_limit;
	/* Mesh files read by earlier frames of an animation (mesh_io.h), or NULL. */
	struct mesh_io_cache *mesh_cache;
	/* File I/O security (eval_access.c): the files a scene may make eclat read
	 * and write. The scene's own folder and the include folders always count;
	 * io_current_folder adds the current one (the command line's), which the
	 * fuzz target leaves out; --io-allow folders are read, --io-allow-write
	 * folders read and written, each with its subfolders. */
	eval_io_security io_security;
	bool io_current_folder;
	const char *const *io_read_dirs;
	int n_io_read_dirs;
	const char *const *io_write_dirs;
	int n_io_write_dirs;
	/* Called with each file the scene reads (includes, meshes, images, fonts,
	 * #fopen), before it is opened, whatever io_security says: a render's
	 * record of its scene hashes them (src/split.h). NULL: not called. */
	void (*on_read)(const char *path, void *ctx);
	void *on_read_ctx;
	/* A pattern or pigment function's pigment at n points p (three doubles a
	 * point) while the scene is read: its pattern's value (colour false:
	 * out[5 * i]) or its colour (out[5 * i ...]: red, green, blue, filter,
	 * transmit); src/device_points.c. 0, or -1 after an error at loc. NULL:
	 * such calls are errors (the fuzz target's). */
	int (*pattern_at)(void *ctx, const scene *s, int pigment, bool colour, int n, const double *p, double *out,
	                  src_loc loc);
	void *pattern_ctx;
} eval_options;

#define EVAL_DEFAULT_INCLUDE_DEPTH 64
#define EVAL_DEFAULT_MACRO_DEPTH 256
#define EVAL_DEFAULT_LOOP_ITERATIONS 1000000L
/* The highest --max-macro-depth: each level is a few C stack frames (see
 * MAX_EXPR_DEPTH in eval_expr.c, which bounds them too). */
#define EVAL_MAX_MACRO_DEPTH_LIMIT 1000

eval_options eval_options_default(void);

/* Fills s (already scene_init'ed) from the file's tree. opt may be NULL for the
 * defaults. Returns 0, or -1 after printing the errors; the scene is then
 * incomplete and must only be freed. #debug text goes to stderr. */
int eval_scene(const ast_node *root, scene *s, const eval_options *opt);

#endif
