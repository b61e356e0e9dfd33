/* render.h: runs the path-tracing kernel over the lowered scene into a film. */
#ifndef ECLAT_RENDER_H
#define ECLAT_RENDER_H

#include "device.h"
#include "film.h"
#include "lower.h"

typedef struct {
	int width, height;
	int samples;      /* per pixel */
	int seed;
	int max_depth;    /* bounces */
	int quiet;
} render_settings;

/* Returns 0 with f filled (film_init'ed here), or -1 after printing the OpenCL error. */
int render_run(device_ctx *d, cl_program prog, lower_result *lr, const render_settings *rs, film *f);

#endif
