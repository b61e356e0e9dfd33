/* render.h: runs the path-tracing kernel over the lowered scene into a film. */
#ifndef ECLAT_RENDER_H
#define ECLAT_RENDER_H

#include <signal.h>
#include <stdint.h>

#include "device.h"
#include "film.h"
#include "lower.h"

typedef struct render_settings {
	int width, height;
	int samples;           /* per pixel, at most */
	int seed;
	int max_depth;         /* bounces */
	int integrator;        /* INTEGRATOR_PATH, INTEGRATOR_NAIVE or INTEGRATOR_WHITTED (whose
	                        * max_depth is max_trace_level, and which needs one sample) */
	float adc_bailout;     /* the Whitted integrator's */
	float gamma;           /* the scene's working gamma (scene.film_gamma) */
	int quiet;
	int aov;               /* 1: keep the first hits' albedo, normal, depth and object (film.aov) */
	double time_limit;     /* seconds; 0: none. The render stops after the pass that passes it. */
	double checkpoint;     /* seconds between calls of on_checkpoint; 0: none */
	int (*on_checkpoint)(const film *f, void *ctx);
	void *ctx;
	volatile sig_atomic_t *stop;  /* set (by a signal handler): finish the pass and return */
	/* In an animation (frames > 1) the progress line names the frame (the
	 * frame_index-th of frames, from 0) and the time the whole animation has
	 * left, reckoned from anim_seconds spent on the frames before this one. */
	long frame, frame_index, frames;
	double anim_seconds;
} render_settings;

typedef struct {
	double seconds;
	long samples;                /* per pixel, done */
	uint64_t counts[COUNT_N];    /* camera, bounce and shadow rays, box and primitive tests */
} render_stats;

/* All rays counted in st. */
double render_rays(const render_stats *st);

/* Renders up to rs->samples samples per pixel into f (film_init'ed here). Returns
 * 0 with f holding the samples done (fewer when stopped or out of time), or -1
 * after printing the OpenCL error. A failure after some passes that still lets
 * the film be read back returns 1, with f holding the samples before it: no
 * lost work. */
int render_run(device_ctx *d, cl_program prog, lower_result *lr, const render_settings *rs, film *f,
               render_stats *st);

#endif
