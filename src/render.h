/* render.h: runs the path-tracing kernel over the lowered scene into a film. */
#ifndef ECLAT_RENDER_H
#define ECLAT_RENDER_H

#include <pthread.h>
#include <signal.h>
#include <stdint.h>

#include "device.h"
#include "film.h"
#include "lower.h"

/* Samples that several devices take passes from (render_multi.c): the next
 * one and the end, absolute sample numbers. */
typedef struct {
	pthread_mutex_t lock;
	int next, end;
	int most;   /* samples a pass takes at most, so that a short render still feeds every device */
	/* the devices' progress, added after each pass: one line for them all */
	int tty;          /* draw it (not quiet, stderr a terminal) */
	int total;        /* the samples the line counts to */
	long done;        /* samples finished */
	double rays, t0;  /* rays traced; when the render began */
} render_queue;

typedef struct render_settings {
	int width, height;
	int samples;           /* per pixel, at most */
	int sample_first;      /* the number of the first sample (--sample-range), for the random numbers */
	const int64_t *start_sums;  /* NULL, or the film's sums of start_samples samples done (--resume) */
	long start_samples;
	int row_first, rows;   /* the rows to render (a region's); rows 0: all */
	render_queue *queue;   /* NULL, or where the passes' samples come from (then samples is ignored) */
	int seed;
	int max_depth;         /* bounces */
	int integrator;        /* INTEGRATOR_PATH, INTEGRATOR_NAIVE or INTEGRATOR_WHITTED (whose
	                        * max_depth is max_trace_level, and which needs one sample) */
	float adc_bailout;     /* the Whitted integrator's */
	/* the Whitted integrator's anti-aliasing (render_aa.c): POV-Ray's method
	 * (0: none, one trace at each pixel's centre; 1 or 2), its threshold, its
	 * depth (+R), the jitter (+J's amount, 0 without) and the exponent its
	 * colour distance takes the colours to (the working gamma over +AG's) */
	int aa_method, aa_depth;
	float aa_threshold, aa_jitter, aa_gamma;
	float gamma;           /* the scene's working gamma (scene.film_gamma) */
	int quiet;
	int aov;               /* 1: keep the first hits' albedo, normal, depth and object (film.aov) */
	double time_limit;     /* seconds; 0: none. The render stops after the pass that passes it. */
	double checkpoint;     /* seconds between calls of on_checkpoint; 0: none */
	int (*on_checkpoint)(const film *f, void *ctx);
	void *ctx;
	volatile sig_atomic_t *stop;  /* set (by a signal handler): finish the pass and return */
	/* Every show_every seconds, between passes, the film so far goes to on_show
	 * (the preview window); its nonzero answer stops the render as *stop does. */
	double show_every;
	int (*on_show)(const film *f, void *ctx);
	void *show_ctx;
	/* In an animation (frames > 1) the progress line names the frame (the
	 * frame_index-th of frames, from 0) and the time the whole animation has
	 * left, reckoned from anim_seconds spent on the frames before this one. */
	long frame, frame_index, frames;
	double anim_seconds;
} render_settings;

typedef struct {
	double seconds;
	long samples;                /* per pixel, done (start_samples included) */
	uint64_t counts[COUNT_N];    /* camera, bounce and shadow rays, box and primitive tests */
} render_stats;

/* All rays counted in st. */
double render_rays(const render_stats *st);
/* Seconds on a monotonic clock. */
double render_now(void);

/* One pass of the Whitted integrator's anti-aliasing over rs's rows into the
 * film buffer, whose kernels take bufs[0 .. n_bufs - 1] first (render_aa.c).
 * Method 1 supersamples in blocks of RENDER_AA_BLOCK rows and columns from the
 * first row (kernels/whitted_pixel.cl's WHITTED_AA_BLOCK), so rows split at
 * block edges give the same pixels. Returns 0, or -1 after printing the
 * OpenCL error. */
#define RENDER_AA_BLOCK 32
int render_aa_pass(device_ctx *d, cl_program prog, const cl_mem *bufs, int n_bufs, const render_settings *rs);

/* Renders up to rs->samples samples per pixel into f (film_init'ed here). Returns
 * 0 with f holding the samples done (fewer when stopped or out of time), or -1
 * after printing the OpenCL error. A failure after some passes that still lets
 * the film be read back returns 1, with f holding the samples before it: no
 * lost work. */
int render_run(device_ctx *d, cl_program prog, lower_result *lr, const render_settings *rs, film *f,
               render_stats *st);

/* Renders rs on several devices at once (render_multi.c): devices idx[0..n-1],
 * or n 0: every device, each with the kernels built for it (kernel_dir as
 * device_build's), taking passes of samples from one queue; their sums add
 * into f exactly, so the image is one device's. name gets the devices' names.
 * Returns as render_run does (a failure after some passes is -1: the samples
 * done need not be the first ones). */
int render_multi(const int *idx, int n, const char *kernel_dir, lower_result *lr, const render_settings *rs,
                 film *f, render_stats *st, char *name, size_t name_len);

#endif
