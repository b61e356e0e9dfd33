/* render_multi.c: one render on several OpenCL devices at once. Each device
 * has its own context, kernels, buffers and film, and a thread that takes the
 * next pass of samples from a shared queue, so a fast device takes more passes
 * than a slow one and none waits for another. The films' sums are integers
 * (kernels/film.cl), so adding them gives exactly the sums of one device. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "render.h"

struct worker {
	device_ctx dev;
	cl_program prog;
	lower_result *lr;
	render_settings rs;
	film f;
	render_stats st;
	pthread_t thread;
	int started, rc;
};

static void *work(void *arg)
{
	struct worker *w = arg;
	w->rc = render_run(&w->dev, w->prog, w->lr, &w->rs, &w->f, &w->st);
	return NULL;
}

/* Opens and builds every device before any renders, so an error in one
 * wastes no time on the others. */
static int prepare(struct worker *w, int n, const int *idx, const char *kernel_dir, lower_result *lr)
{
	for (int i = 0; i < n; i++) {
		if (device_open(&w[i].dev, idx ? idx[i] : i))
			return -1;
		w[i].prog = device_build(&w[i].dev, kernel_dir, lower_kernel_options(lr), lr->functions);
		if (!w[i].prog)
			return -1;
		w[i].lr = lr;
	}
	return 0;
}

/* The devices' sums and counters into f and st. */
static int gather(struct worker *w, int n, const render_settings *rs, film *f, render_stats *st)
{
	if (film_init(f, rs->width, rs->height, rs->aov))
		return -1;
	size_t npix = (size_t)rs->width * rs->height;
	memset(st, 0, sizeof *st);
	for (int i = 0; i < n; i++) {
		for (size_t k = 0; k < npix * 4; k++)
			f->sums[k] += w[i].f.sums[k];
		for (size_t k = 0; f->aov && k < npix * AOV_FLOAT4S * 4; k++)
			f->aov[k] += w[i].f.aov[k];
		for (int c = 0; c < COUNT_N; c++)
			st->counts[c] += w[i].st.counts[c];
		st->samples += w[i].st.samples;
		if (w[i].st.seconds > st->seconds)
			st->seconds = w[i].st.seconds;
	}
	film_resolve(f, f->sums, st->samples, rs->gamma);
	return 0;
}

static void names(const struct worker *w, int n, char *name, size_t len)
{
	size_t at = (size_t)snprintf(name, len, "%d devices (", n);
	for (int i = 0; i < n && at < len; i++)
		at += (size_t)snprintf(name + at, len - at, "%s%s", i ? ", " : "", w[i].dev.name);
	if (at < len)
		snprintf(name + at, len - at, ")");
}

int render_multi(const int *idx, int n, const char *kernel_dir, lower_result *lr, const render_settings *rs,
                 film *f, render_stats *st, char *name, size_t name_len)
{
	if (n == 0 && (n = device_count()) < 0)
		return -1;
	struct worker *w = calloc((size_t)n, sizeof *w);
	render_queue q = { .next = rs->sample_first + (int)rs->start_samples, .end = rs->sample_first + rs->samples,
		           .tty = !rs->quiet && isatty(STDERR_FILENO), .total = rs->samples, .done = rs->start_samples };
	q.most = (q.end - q.next) / (2 * n) > 1 ? (q.end - q.next) / (2 * n) : 1;
	if (!w || pthread_mutex_init(&q.lock, NULL)) {
		free(w);
		return -1;
	}
	int rc = prepare(w, n, idx, kernel_dir, lr);
	q.t0 = render_now();   /* after the builds, as one device's line counts */
	for (int i = 0; i < n && rc == 0; i++) {
		w[i].rs = *rs;
		w[i].rs.queue = &q;
		w[i].rs.quiet = 1;
		w[i].rs.checkpoint = 0;           /* the devices' films are whole only together */
		if (i > 0)
			w[i].rs.start_sums = NULL;    /* a resumed render's sums are added once */
		w[i].started = pthread_create(&w[i].thread, NULL, work, &w[i]) == 0;
		rc = w[i].started ? 0 : -1;
	}
	for (int i = 0; i < n; i++)
		if (w[i].started) {
			pthread_join(w[i].thread, NULL);
			rc = rc || w[i].rc ? -1 : 0;   /* a device lost midway leaves a gap in the samples */
		}
	if (q.tty && q.done > rs->start_samples)
		fputc('\n', stderr);
	if (rc == 0)
		rc = gather(w, n, rs, f, st);
	names(w, n, name, name_len);
	for (int i = 0; i < n; i++) {
		film_free(&w[i].f);
		if (w[i].prog)
			clReleaseProgram(w[i].prog);
		device_close(&w[i].dev);
	}
	pthread_mutex_destroy(&q.lock);
	free(w);
	return rc;
}
