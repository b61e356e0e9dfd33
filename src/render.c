/* render.c: device buffers, kernel arguments and the progressive sample loop,
 * with progress, a time limit, checkpoints and clean stops between passes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "render.h"

#define WHITTED_GROUP 16

/* Where each of the scene's buffers (SCENE_BUFFERS in shared.h) is on the
 * host: pointer and bytes. A buffer added to that list needs a line here. */
#define HOST_nodes(LR) (LR)->dev_nodes, (LR)->dev_node_bytes
#define HOST_prims(LR) (LR)->prims, (LR)->n_all_prims * sizeof(dev_prim)
#define HOST_normals(LR) (LR)->normals, (LR)->n_normals * sizeof(float4)
#define HOST_materials(LR) (LR)->materials, (LR)->n_materials * sizeof(dev_material)
#define HOST_lights(LR) (LR)->lights, (LR)->n_lights * sizeof(dev_light)
#define HOST_emitters(LR) (LR)->emitters, (LR)->n_emitters * sizeof(dev_emitter)
#define HOST_objects(LR) (LR)->object_flags, (LR)->n_objects * sizeof(cl_int)
#define HOST_patterns(LR) (LR)->textures.patterns, (LR)->textures.n_patterns * sizeof(dev_pattern)
#define HOST_warps(LR) (LR)->textures.warps, (LR)->textures.n_warps * sizeof(dev_warp)
#define HOST_maps(LR) (LR)->textures.maps, (LR)->textures.n_maps * sizeof(dev_map_entry)
#define HOST_images(LR) (LR)->textures.images, (LR)->textures.n_images * sizeof(dev_image)
#define HOST_texels(LR) (LR)->textures.texels, (LR)->textures.n_texels * sizeof(float4)
#define HOST_fogs(LR) (LR)->fogs, (LR)->n_fogs * sizeof(dev_fog)
#define HOST_rainbows(LR) (LR)->rainbows, (LR)->n_rainbows * sizeof(dev_rainbow)
#define HOST_camera_rays(LR) (LR)->camera_rays, (size_t)(LR)->n_camera_rays * sizeof(float4)
#define HOST_media(LR) (LR)->textures.media, (LR)->textures.n_media * sizeof(dev_media)
#define HOST_sky_dist(LR) &(LR)->sky, sizeof(dev_sky)
#define HOST_sky_cdf(LR) (LR)->sky_cdf, (LR)->n_sky_cdf * sizeof(float)

/* The kernels' buffers in argument order: the scene's, from shared.h's list,
 * then the parameters and the film's. */
enum {
#define SCENE_ENUM(TYPE, NAME) BUF_##NAME,
	SCENE_BUFFERS(SCENE_ENUM)
#undef SCENE_ENUM
	BUF_params, BUF_film, BUF_counters, BUF_aov,
	BUF_COUNT
};

struct host_buffer {
	const char *name;
	const void *ptr;     /* what the buffer starts with, or NULL */
	size_t bytes;
	cl_mem_flags flags;
};

/* Every buffer's name, contents and size, in argument order. */
static void buffer_table(const lower_result *lr, const dev_params *params, size_t npix,
                         struct host_buffer b[BUF_COUNT])
{
#define SCENE_ROW(TYPE, NAME) b[BUF_##NAME] = (struct host_buffer){ #NAME, HOST_##NAME(lr), CL_MEM_READ_ONLY };
	SCENE_BUFFERS(SCENE_ROW)
#undef SCENE_ROW
	b[BUF_params] = (struct host_buffer){ "params", params, sizeof *params, CL_MEM_READ_ONLY };
	b[BUF_film] = (struct host_buffer){ "film", NULL, npix * 4 * sizeof(cl_long), CL_MEM_READ_WRITE };
	b[BUF_counters] = (struct host_buffer){ "counters", NULL, COUNT_N * sizeof(cl_uint), CL_MEM_READ_WRITE };
	b[BUF_aov] = (struct host_buffer){ "aov", NULL, params->aov ? npix * AOV_FLOAT4S * 4 * sizeof(float) : 0,
	                                   CL_MEM_READ_WRITE };
}

struct pass_loop {
	device_ctx *d;
	cl_program prog;     /* for the anti-aliasing's kernels */
	cl_kernel k;
	cl_mem bufs[BUF_COUNT];
	dev_params params;
	size_t npix;
	const render_settings *rs;
	render_stats *st;
	int64_t *sums;
	double t0;
	film *f;
	double last_show, show_cost;   /* when the window was last shown the film, and what it took */
};

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static double gib(double bytes)
{
	return bytes / (1024.0 * 1024.0 * 1024.0);
}

/* Says which buffer does not fit the device, with the numbers, before any is made. */
static int check_fits(const device_ctx *d, const struct host_buffer b[BUF_COUNT])
{
	double total = 0;
	for (int i = 0; i < BUF_COUNT; i++) {
		if ((double)b[i].bytes > (double)d->max_alloc) {
			fprintf(stderr, "eclat: the %s buffer needs %.2f GiB, more than the %.2f GiB %s allows "
			        "in one buffer\n", b[i].name, gib(b[i].bytes), gib(d->max_alloc), d->name);
			return -1;
		}
		total += (double)b[i].bytes;
	}
	if (total > (double)d->global_mem) {
		fprintf(stderr, "eclat: the scene and image need %.2f GiB, more than the %.2f GiB of %s\n",
		        gib(total), gib(d->global_mem), d->name);
		return -1;
	}
	return 0;
}

/* OpenCL refuses zero-sized buffers; an empty list still gets one element. */
static cl_mem make_buffer(device_ctx *d, const void *host, size_t bytes, cl_mem_flags flags, cl_int *err)
{
	if (bytes == 0) {
		bytes = 16;
		host = NULL;
	}
	if (host)
		flags |= CL_MEM_COPY_HOST_PTR;
	return clCreateBuffer(d->context, flags, bytes, (void *)host, err);
}

static void format_time(double s, char *out, size_t n)
{
	long t = (long)(s + 0.5);
	if (t >= 3600)
		snprintf(out, n, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
	else
		snprintf(out, n, "%ld:%02ld", t / 60, t % 60);
}

double render_now(void)
{
	return now();
}

double render_rays(const render_stats *st)
{
	return (double)st->counts[COUNT_RAYS + RAY_CAMERA] + st->counts[COUNT_RAYS + RAY_BOUNCE] +
	       st->counts[COUNT_RAYS + RAY_SHADOW];
}

/* One line, redrawn in place: samples, speed, time spent and left (in an
 * animation: the frame, and the time left for the frames still to come, at
 * the pace of those done and of this one so far). */
static void progress_line(const render_settings *rs, long samples, int total, double run, double rays,
                          size_t npix)
{
	double el = run, frac = (double)samples / total;
	int width = 24, bar = (int)(frac * width);
	double left_s = frac > 0 ? el / frac - el : 0;
	char elapsed[48], left[48], frame[64] = "";
	if (rs->frames > 1) {
		double done = rs->frame_index + frac;
		left_s = done > 0 ? (rs->anim_seconds + el) / done * (rs->frames - done) : 0;
		el += rs->anim_seconds;
		snprintf(frame, sizeof frame, "frame %ld (%ld/%ld) ", rs->frame, rs->frame_index + 1, rs->frames);
	}
	format_time(el, elapsed, sizeof elapsed);
	format_time(left_s, left, sizeof left);
	fprintf(stderr, "\r%s%3d%% [%.*s%*s] %ld/%d samples  %.2f M paths/s  %.2f M rays/s  %s elapsed  %s left ",
	        frame, (int)(100 * frac), bar, "========================", width - bar, "", samples, total,
	        npix * (double)samples / run * 1e-6, rays / run * 1e-6, elapsed, left);
}

static void progress(const struct pass_loop *pl)
{
	progress_line(pl->rs, pl->st->samples, pl->rs->samples, now() - pl->t0, render_rays(pl->st), pl->npix);
}

/* A pass of count samples done on one of several devices (render_multi.c):
 * the shared line, drawn under the queue's lock so that lines never mix. */
static void progress_shared(const struct pass_loop *pl, int count, double rays)
{
	render_queue *q = pl->rs->queue;
	pthread_mutex_lock(&q->lock);
	q->done += count;
	q->rays += rays;
	if (q->tty)
		progress_line(pl->rs, q->done, q->total, now() - q->t0, q->rays, pl->npix);
	pthread_mutex_unlock(&q->lock);
}

/* f from the device's film, whose pixels hold samples samples each. */
static int read_film_at(struct pass_loop *pl, film *f, long samples)
{
	cl_int err = clEnqueueReadBuffer(pl->d->queue, pl->bufs[BUF_film], CL_TRUE, 0,
	                                 pl->npix * 4 * sizeof *pl->sums, pl->sums, 0, NULL, NULL);
	if (err == CL_SUCCESS && f->aov)
		err = clEnqueueReadBuffer(pl->d->queue, pl->bufs[BUF_aov], CL_TRUE, 0,
		                          pl->npix * AOV_FLOAT4S * 4 * sizeof(float), f->aov, 0, NULL, NULL);
	if (err != CL_SUCCESS)
		return device_fail("clEnqueueReadBuffer", err);
	film_resolve(f, pl->sums, samples, pl->rs->gamma);
	return 0;
}

static int read_film(struct pass_loop *pl, film *f)
{
	return read_film_at(pl, f, pl->st->samples);
}

/* Shows the window the film, of samples samples a pixel, when that is due:
 * every show_every seconds, and less often when a large film takes a while
 * to read and show (0.27 s at 1920x1080 here): at most a twentieth of the
 * render goes to it. Returns 1 when the window asks for a stop, -1 when the
 * film could not be read. */
static int show(struct pass_loop *pl, long samples)
{
	const render_settings *rs = pl->rs;
	double t = now();
	if (!rs->on_show || t - pl->last_show < fmax(rs->show_every, 20 * pl->show_cost))
		return 0;
	if (read_film_at(pl, pl->f, samples))
		return -1;
	int stop = rs->on_show(pl->f, rs->show_ctx);
	pl->last_show = now();
	pl->show_cost = pl->last_show - t;
	return stop;
}

/* The size of the bands a Whitted pass of n units runs in: all n at once, or
 * when a window shows the render and this pass holds all the samples
 * (POV-Ray's one pass), about a sixteenth of them in whole multiples of unit,
 * each band shown as it ends: a band done is final. */
static size_t whitted_band(const struct pass_loop *pl, int count, size_t n, size_t unit)
{
	const render_settings *rs = pl->rs;
	if (!rs->on_show || pl->st->samples != 0 || count != rs->samples)
		return n;
	return ((n + 15) / 16 + unit - 1) / unit * unit;
}

/* The Whitted kernel over pixels first to first + n - 1 (in groups of local:
 * see run_pass), in whitted_band's bands of whole groups (no pixel twice). A
 * stop asked for waits for the pass's end. */
static int launch_whitted(struct pass_loop *pl, size_t first, size_t n, size_t local, int count)
{
	size_t band = whitted_band(pl, count, n, local);
	for (size_t done = 0; done < n; done += band) {
		size_t at = first + done, m = n - done < band ? n - done : band;
		size_t global = (m + local - 1) / local * local;
		cl_int err = clEnqueueNDRangeKernel(pl->d->queue, pl->k, 1, &at, &global, &local, 0, NULL, NULL);
		if (err != CL_SUCCESS)
			return device_fail("clEnqueueNDRangeKernel", err);
		if (band == n || done + m == n)
			continue;
		if ((err = clFinish(pl->d->queue)) != CL_SUCCESS)
			return device_fail("clFinish", err);
		if (show(pl, count) < 0)
			return -1;
	}
	return 0;
}

/* The Whitted integrator's anti-aliased pass (render_aa.c), in whitted_band's
 * bands of whole blocks of rows (method 1's blocks start at the first row, so
 * each band's pixels are the whole pass's). */
static int launch_whitted_aa(struct pass_loop *pl, int count)
{
	const render_settings *rs = pl->rs;
	int first = rs->rows ? rs->row_first : 0, rows = rs->rows ? rs->rows : rs->height;
	int band = (int)whitted_band(pl, count, (size_t)rows, RENDER_AA_BLOCK);
	for (int done = 0; done < rows; done += band) {
		render_settings part = *rs;
		part.row_first = first + done;
		part.rows = rows - done < band ? rows - done : band;
		if (render_aa_pass(pl->d, pl->prog, pl->bufs, BUF_COUNT, &part))
			return -1;
		if (done + part.rows < rows && show(pl, count) < 0)
			return -1;
	}
	return 0;
}

/* ECLAT_TEST_FAIL_PASS=N makes pass N (from 1) fail as a lost device would, so
 * that tests can check that the samples before it are kept. */
static int injected_failure(void)
{
	static int passes;
	const char *s = getenv("ECLAT_TEST_FAIL_PASS");
	return s && ++passes == atoi(s);
}

/* Samples base to base + count - 1 of every pixel (of its rows). */
static int run_pass(struct pass_loop *pl, int base, int count)
{
	cl_uint counts[COUNT_N] = { 0 };
	if (injected_failure())
		return device_fail("clEnqueueNDRangeKernel", CL_OUT_OF_RESOURCES);
	pl->params.sample_base = base;
	pl->params.samples_per_pass = count;
	cl_int err = clEnqueueWriteBuffer(pl->d->queue, pl->bufs[BUF_params], CL_TRUE, 0, sizeof pl->params,
	                                  &pl->params, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueWriteBuffer(pl->d->queue, pl->bufs[BUF_counters], CL_TRUE, 0, sizeof counts,
		                           counts, 0, NULL, NULL);
	if (err != CL_SUCCESS)
		return device_fail("clEnqueueWriteBuffer", err);
	/* The Whitted kernel keeps a stack of ray frames per work item; PoCL puts a
	 * work group's private arrays on one thread's stack, so its groups are kept
	 * small (the kernel ignores the work items past the last pixel). */
	const render_settings *rs = pl->rs;
	size_t first = rs->rows ? (size_t)rs->row_first * rs->width : 0;
	size_t n = rs->rows ? (size_t)rs->rows * rs->width : pl->npix;
	if (pl->params.integrator == INTEGRATOR_WHITTED && rs->aa_method > 0) {
		if (launch_whitted_aa(pl, count))
			return -1;
	} else if (pl->params.integrator == INTEGRATOR_WHITTED) {
		if (launch_whitted(pl, first, n, WHITTED_GROUP, count))
			return -1;
	} else {
		err = clEnqueueNDRangeKernel(pl->d->queue, pl->k, 1, &first, &n, NULL, 0, NULL, NULL);
		if (err != CL_SUCCESS)
			return device_fail("clEnqueueNDRangeKernel", err);
	}
	err = clEnqueueReadBuffer(pl->d->queue, pl->bufs[BUF_counters], CL_TRUE, 0, sizeof counts, counts,
	                          0, NULL, NULL);
	if (err != CL_SUCCESS)
		return device_fail("clEnqueueReadBuffer", err);
	for (int i = 0; i < COUNT_N; i++)
		pl->st->counts[i] += counts[i];
	pl->st->samples += count;
	return 0;
}

/* Samples per launch: about a quarter of a million paths, so a pass is short (a
 * stop or a checkpoint waits for at most one) and the 32-bit counters cannot
 * overflow. It depends on the image size only, never on timing: the film adds
 * samples one by one, so the pixels do not depend on it either. */
static int pass_size(size_t npix)
{
	size_t k = (1u << 18) / (npix ? npix : 1);
	return k < 1 ? 1 : k > 64 ? 64 : (int)k;
}

/* The next pass's samples: the next of this render's, or of the queue that
 * several devices share. 0 when there are none left. */
static int next_pass(struct pass_loop *pl, int per, int *base, int *count)
{
	const render_settings *rs = pl->rs;
	render_queue *q = rs->queue;
	if (!q) {
		int left = rs->samples - (int)pl->st->samples;
		*base = rs->sample_first + (int)pl->st->samples;
		*count = left < per ? left : per;
		return left > 0;
	}
	pthread_mutex_lock(&q->lock);
	int left = q->end - q->next;
	per = per < q->most ? per : q->most;
	*base = q->next;
	*count = left < per ? left : per;
	q->next += left > 0 ? *count : 0;
	pthread_mutex_unlock(&q->lock);
	return left > 0;
}

static int run_passes(struct pass_loop *pl, film *f)
{
	const render_settings *rs = pl->rs;
	float zero = 0.0f;
	cl_int err;
	if (rs->start_sums)
		err = clEnqueueWriteBuffer(pl->d->queue, pl->bufs[BUF_film], CL_TRUE, 0, pl->npix * 4 * sizeof(cl_long),
		                           rs->start_sums, 0, NULL, NULL);
	else
		err = clEnqueueFillBuffer(pl->d->queue, pl->bufs[BUF_film], &zero, sizeof zero, 0,
		                          pl->npix * 4 * sizeof(cl_long), 0, NULL, NULL);
	pl->st->samples = rs->start_sums ? rs->start_samples : 0;
	if (err == CL_SUCCESS && pl->params.aov)
		err = clEnqueueFillBuffer(pl->d->queue, pl->bufs[BUF_aov], &zero, sizeof zero, 0,
		                          pl->npix * AOV_FLOAT4S * 4 * sizeof(float), 0, NULL, NULL);
	if (err != CL_SUCCESS)
		return device_fail("clEnqueueFillBuffer", err);
	int tty = !rs->quiet && isatty(STDERR_FILENO), per = pass_size(pl->npix);
	double last_checkpoint = pl->t0;
	int base, count;
	while (next_pass(pl, per, &base, &count)) {
		double rays = render_rays(pl->st);
		if (run_pass(pl, base, count)) {
			if (tty)
				fputc('\n', stderr);
			/* keep the passes done, when the device still gives them back */
			return pl->st->samples > 0 && read_film(pl, f) == 0 ? 1 : -1;
		}
		if (tty)
			progress(pl);
		if (rs->queue)
			progress_shared(pl, count, render_rays(pl->st) - rays);
		int shown = pl->st->samples < rs->samples ? show(pl, pl->st->samples) : 0;
		if (shown < 0)
			return -1;
		if (shown)
			break;
		if ((rs->stop && *rs->stop) || (rs->time_limit > 0 && now() - pl->t0 >= rs->time_limit))
			break;
		if (rs->checkpoint > 0 && rs->on_checkpoint && now() - last_checkpoint >= rs->checkpoint &&
		    pl->st->samples < rs->samples) {
			if (read_film(pl, f) || rs->on_checkpoint(f, rs->ctx))
				return -1;
			last_checkpoint = now();
		}
	}
	if (tty)
		fputc('\n', stderr);
	return read_film(pl, f);
}

static int setup(struct pass_loop *pl, cl_program prog, lower_result *lr)
{
	cl_int err;
	/* the integrators' kernels take the same buffers first, and a program
	 * holds only those its render launches (LOWER_KERNELS_) */
	const char *name = pl->params.integrator != INTEGRATOR_WHITTED ? "render_pass"
	                   : pl->rs->aa_method > 0                     ? "whitted_aa_grid"
	                                                               : "render_whitted";
	pl->k = clCreateKernel(prog, name, &err);
	if (!pl->k)
		return device_fail("clCreateKernel", err);
	err = CL_SUCCESS;
	struct host_buffer b[BUF_COUNT];
	buffer_table(lr, &pl->params, pl->npix, b);
	for (int i = 0; i < BUF_COUNT && err == CL_SUCCESS; i++)
		pl->bufs[i] = make_buffer(pl->d, b[i].ptr, b[i].bytes, b[i].flags, &err);
	if (err != CL_SUCCESS)
		return device_fail("clCreateBuffer", err);
	for (int i = 0; i < BUF_COUNT && err == CL_SUCCESS; i++)
		err = clSetKernelArg(pl->k, i, sizeof(cl_mem), &pl->bufs[i]);
	return err == CL_SUCCESS ? 0 : device_fail("clSetKernelArg", err);
}

int render_run(device_ctx *d, cl_program prog, lower_result *lr, const render_settings *rs, film *f,
               render_stats *st)
{
	struct pass_loop pl = { .d = d, .prog = prog, .npix = (size_t)rs->width * rs->height, .rs = rs, .st = st };
	memset(st, 0, sizeof *st);
	pl.params = lr->params;
	pl.params.width = rs->width;
	pl.params.height = rs->height;
	pl.params.max_depth = rs->max_depth;
	pl.params.seed = rs->seed;
	pl.params.integrator = rs->integrator;
	pl.params.n_lights = lr->n_lights;
	pl.params.n_prims = lr->n_prims;
	pl.params.n_planes = lr->n_planes;
	pl.params.n_emitters = lr->n_emitters;
	pl.params.aov = rs->aov;
	pl.params.classic.w = rs->adc_bailout;
	struct host_buffer table[BUF_COUNT];
	buffer_table(lr, &pl.params, pl.npix, table);
	if (check_fits(d, table))
		return -1;
	int rc = -1;
	pl.sums = malloc(pl.npix * 4 * sizeof *pl.sums);
	if (!pl.sums || film_init(f, rs->width, rs->height, rs->aov)) {
		fprintf(stderr, "eclat: out of memory for a %dx%d film\n", rs->width, rs->height);
		goto out;
	}
	if (setup(&pl, prog, lr) == 0) {
		pl.t0 = pl.last_show = now();
		pl.f = f;
		rc = run_passes(&pl, f);
		st->seconds = now() - pl.t0;
	}
	if (rc < 0)
		film_free(f);
out:
	free(pl.sums);
	for (int i = 0; i < BUF_COUNT; i++)
		if (pl.bufs[i])
			clReleaseMemObject(pl.bufs[i]);
	if (pl.k)
		clReleaseKernel(pl.k);
	return rc;
}
