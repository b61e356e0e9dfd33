/* render_multi.c: one render on several OpenCL devices at once. Each device
 * has its own context, kernels, buffers and film, and a thread that takes the
 * next pass of samples from a shared queue, so a fast device takes more passes
 * than a slow one and none waits for another. The films' sums are integers
 * (kernels/film.cl), so adding them gives exactly the sums of one device.
 * A preview window is shown by the calling thread (the one that opened it):
 * each device's thread hands over a copy of its film when its own show is
 * due, and the calling thread adds the copies up and shows them. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "render.h"

/* What the device threads hand over for the window, under lock. */
struct handover {
	pthread_mutex_t lock;
	int fresh;      /* a film came since the last show */
	int running;    /* device threads not yet done */
};

struct worker {
	device_ctx dev;
	cl_program prog;
	lower_result *lr;
	render_settings rs;
	film f;
	render_stats st;
	pthread_t thread;
	int started, rc;
	struct handover *ho;   /* NULL: no window */
	int64_t *snap;         /* the last film handed over: its sums and samples */
	long snap_samples;
};

/* A device thread's show (render_run's on_show): a copy of its film for the
 * calling thread. A stop the window asks for reaches the devices through
 * rs.stop, as Ctrl-C's does. */
static int hand_over(const film *f, void *ctx)
{
	struct worker *w = ctx;
	size_t n = (size_t)f->width * f->height * 4;
	pthread_mutex_lock(&w->ho->lock);
	if (!w->snap)
		w->snap = malloc(n * sizeof *w->snap);
	if (w->snap) {
		memcpy(w->snap, f->sums, n * sizeof *w->snap);
		w->snap_samples = f->samples;
		w->ho->fresh = 1;
	}
	pthread_mutex_unlock(&w->ho->lock);
	return 0;
}

static void *work(void *arg)
{
	struct worker *w = arg;
	w->rc = render_run(&w->dev, w->prog, w->lr, &w->rs, &w->f, &w->st);
	if (w->ho) {
		pthread_mutex_lock(&w->ho->lock);
		w->ho->running--;
		pthread_mutex_unlock(&w->ho->lock);
	}
	return NULL;
}

/* Until the device threads are done, every show_every seconds, the films they
 * handed over added up in the window (rs->on_show, on this thread). */
static void watch(struct worker *w, int n, struct handover *ho, const render_settings *rs)
{
	film shown = { 0 };
	size_t count = (size_t)rs->width * rs->height * 4;
	int64_t *sum = malloc(count * sizeof *sum);
	int ok = sum && film_init(&shown, rs->width, rs->height, 0) == 0;
	for (;;) {
		struct timespec ts = { (time_t)rs->show_every, (long)((rs->show_every - (time_t)rs->show_every) * 1e9) };
		nanosleep(&ts, NULL);
		long samples = 0;
		pthread_mutex_lock(&ho->lock);
		int running = ho->running, fresh = ho->fresh;
		ho->fresh = 0;
		if (ok && fresh) {
			memset(sum, 0, count * sizeof *sum);
			for (int i = 0; i < n; i++)
				for (size_t k = 0; w[i].snap && k < count; k++)
					sum[k] += w[i].snap[k];
			for (int i = 0; i < n; i++)
				samples += w[i].snap ? w[i].snap_samples : 0;
		}
		pthread_mutex_unlock(&ho->lock);
		if (running == 0)
			break;
		if (ok && fresh && samples > 0) {
			film_resolve(&shown, sum, samples, rs->gamma);
			rs->on_show(&shown, rs->show_ctx);   /* a stop it asks for comes back through rs->stop */
		}
	}
	film_free(&shown);
	free(sum);
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
	struct handover ho = { .running = 0 };
	int window = rs->on_show && pthread_mutex_init(&ho.lock, NULL) == 0;
	q.t0 = render_now();   /* after the builds, as one device's line counts */
	for (int i = 0; i < n && rc == 0; i++) {
		w[i].rs = *rs;
		w[i].rs.queue = &q;
		w[i].rs.quiet = 1;
		w[i].rs.checkpoint = 0;           /* the devices' films are whole only together */
		w[i].rs.on_show = window ? hand_over : NULL;
		w[i].rs.show_ctx = &w[i];
		w[i].ho = window ? &ho : NULL;
		if (i > 0)
			w[i].rs.start_sums = NULL;    /* a resumed render's sums are added once */
		w[i].started = pthread_create(&w[i].thread, NULL, work, &w[i]) == 0;
		if (w[i].started && window) {   /* it may be done already: running is read only by watch, after */
			pthread_mutex_lock(&ho.lock);
			ho.running++;
			pthread_mutex_unlock(&ho.lock);
		}
		rc = w[i].started ? 0 : -1;
	}
	if (window)
		watch(w, n, &ho, rs);
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
		free(w[i].snap);
		film_free(&w[i].f);
		if (w[i].prog)
			clReleaseProgram(w[i].prog);
		device_close(&w[i].dev);
	}
	pthread_mutex_destroy(&q.lock);
	if (window)
		pthread_mutex_destroy(&ho.lock);
	free(w);
	return rc;
}
