/* render_keep.h: what the frames of an animation share in one process: the
 * OpenCL device, the kernels built for it (rebuilt only when their source or
 * options change: a scene's functions are part of the source) and the meshes'
 * BVHs (lower_cache).
 *
 *   render_keep k = { 0 };
 *   for each frame: lower with lo.cache = render_keep_cache(&k), then
 *       prog = render_keep_program(&k, index, kernel_dir, &lr);   (NULL: failed)
 *       render_run(&k.dev, prog, ...)
 *   render_keep_free(&k); */
#ifndef ECLAT_RENDER_KEEP_H
#define ECLAT_RENDER_KEEP_H

#include "device.h"
#include "lower.h"

typedef struct {
	device_ctx dev;
	int opened;          /* 1: dev is open; -1: opening it failed */
	cl_program prog;
	char *prog_key;      /* the options and the scene's functions prog was built with */
	int builds;          /* how often the kernels were built */
	lower_cache *bvhs;
} render_keep;

/* The cache of meshes' BVHs, made on first use (NULL when out of memory,
 * which only costs the builds). */
lower_cache *render_keep_cache(render_keep *k);

/* The device (index as device_open's, opened on the first call) and the
 * kernels for lr, built unless those of the previous call fit. Returns NULL
 * after printing why. */
cl_program render_keep_program(render_keep *k, int index, const char *kernel_dir, const lower_result *lr);

void render_keep_free(render_keep *k);

#endif
