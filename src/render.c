/* render.c: device buffers, kernel arguments and the progressive sample loop. */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "render.h"

/* The kernel's buffers in argument order (an X-macro, so creating, binding and
 * releasing them cannot drift apart): name, host pointer, bytes, flags. */
#define RENDER_BUFFERS(X, LR, PARAMS, NPIX) \
	X(nodes, (LR)->bvh.nodes, (LR)->bvh.n_nodes * sizeof(bvh_node), CL_MEM_READ_ONLY) \
	X(prims, (LR)->prims, (LR)->n_prims * sizeof(dev_prim), CL_MEM_READ_ONLY) \
	X(materials, (LR)->materials, (LR)->n_materials * sizeof(dev_material), CL_MEM_READ_ONLY) \
	X(lights, (LR)->lights, (LR)->n_lights * sizeof(dev_light), CL_MEM_READ_ONLY) \
	X(params, (PARAMS), sizeof(dev_params), CL_MEM_READ_ONLY) \
	X(film, NULL, (NPIX) * 4 * sizeof(float), CL_MEM_READ_WRITE)

enum {
#define X(NAME, PTR, BYTES, FLAGS) BUF_##NAME,
	RENDER_BUFFERS(X, 0, 0, 0)
#undef X
	BUF_COUNT
};

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + ts.tv_nsec * 1e-9;
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

static int run_passes(device_ctx *d, cl_kernel k, cl_mem *bufs, dev_params *params,
                      const render_settings *rs, size_t npix)
{
	cl_int err;
	float zero = 0.0f;
	err = clEnqueueFillBuffer(d->queue, bufs[BUF_film], &zero, sizeof zero, 0, npix * 4 * sizeof(float),
	                          0, NULL, NULL);
	if (err != CL_SUCCESS)
		return device_fail("clEnqueueFillBuffer", err);
	/* A few samples per launch: launches stay short, so progress can be reported
	 * and a later interrupt loses little. */
	for (int done = 0; done < rs->samples;) {
		params->sample_base = done;
		params->samples_per_pass = rs->samples - done < 4 ? rs->samples - done : 4;
		err = clEnqueueWriteBuffer(d->queue, bufs[BUF_params], CL_TRUE, 0, sizeof *params, params,
		                           0, NULL, NULL);
		if (err != CL_SUCCESS)
			return device_fail("clEnqueueWriteBuffer", err);
		err = clEnqueueNDRangeKernel(d->queue, k, 1, NULL, &npix, NULL, 0, NULL, NULL);
		if (err != CL_SUCCESS)
			return device_fail("clEnqueueNDRangeKernel", err);
		done += params->samples_per_pass;
	}
	err = clFinish(d->queue);
	return err == CL_SUCCESS ? 0 : device_fail("clFinish", err);
}

static double gib(double bytes)
{
	return bytes / (1024.0 * 1024.0 * 1024.0);
}

/* Says which buffer does not fit the device, with the numbers, before any is made. */
static int check_fits(const device_ctx *d, lower_result *lr, const dev_params *params, size_t npix)
{
	double total = 0;
	(void)params;
#define X(NAME, PTR, BYTES, FLAGS) \
	if ((double)(BYTES) > (double)d->max_alloc) { \
		fprintf(stderr, "eclat: the %s buffer needs %.2f GiB, more than the %.2f GiB %s allows " \
		        "in one buffer\n", #NAME, gib(BYTES), gib(d->max_alloc), d->name); \
		return -1; \
	} \
	total += (double)(BYTES);
	RENDER_BUFFERS(X, lr, params, npix)
#undef X
	if (total > (double)d->global_mem) {
		fprintf(stderr, "eclat: the scene and image need %.2f GiB, more than the %.2f GiB of %s\n",
		        gib(total), gib(d->global_mem), d->name);
		return -1;
	}
	return 0;
}

int render_run(device_ctx *d, cl_program prog, lower_result *lr, const render_settings *rs, film *f)
{
	size_t npix = (size_t)rs->width * rs->height;
	dev_params params = lr->params;
	params.width = rs->width;
	params.height = rs->height;
	params.max_depth = rs->max_depth;
	params.seed = rs->seed;
	params.n_lights = lr->n_lights;
	params.n_prims = lr->n_prims;

	if (check_fits(d, lr, &params, npix))
		return -1;
	cl_int err = CL_SUCCESS;
	cl_mem bufs[BUF_COUNT] = { 0 };
	int rc = -1;
	float *sums = NULL;
	cl_kernel k = clCreateKernel(prog, "render_pass", &err);
	if (!k)
		return device_fail("clCreateKernel", err);
#define X(NAME, PTR, BYTES, FLAGS) \
	if (err == CL_SUCCESS) \
		bufs[BUF_##NAME] = make_buffer(d, PTR, BYTES, FLAGS, &err);
	RENDER_BUFFERS(X, lr, &params, npix)
#undef X
	if (err != CL_SUCCESS) {
		device_fail("clCreateBuffer", err);
		goto out;
	}
	for (int i = 0; i < BUF_COUNT && err == CL_SUCCESS; i++)
		err = clSetKernelArg(k, i, sizeof(cl_mem), &bufs[i]);
	if (err != CL_SUCCESS) {
		device_fail("clSetKernelArg", err);
		goto out;
	}

	double t0 = now();
	if (run_passes(d, k, bufs, &params, rs, npix))
		goto out;
	sums = malloc(npix * 4 * sizeof *sums);
	if (!sums || film_init(f, rs->width, rs->height)) {
		fprintf(stderr, "eclat: out of memory for a %dx%d film\n", rs->width, rs->height);
		goto out;
	}
	err = clEnqueueReadBuffer(d->queue, bufs[BUF_film], CL_TRUE, 0, npix * 4 * sizeof *sums, sums,
	                          0, NULL, NULL);
	if (err != CL_SUCCESS) {
		device_fail("clEnqueueReadBuffer", err);
		film_free(f);
		goto out;
	}
	film_resolve(f, sums, rs->samples);
	double secs = now() - t0;
	if (!rs->quiet)
		fprintf(stderr, "eclat: %dx%d, %d samples in %.2f s on %s (%.2f M paths/s)\n", rs->width,
		        rs->height, rs->samples, secs, d->name, npix * (double)rs->samples / secs * 1e-6);
	rc = 0;
out:
	free(sums);
	for (int i = 0; i < BUF_COUNT; i++)
		if (bufs[i])
			clReleaseMemObject(bufs[i]);
	clReleaseKernel(k);
	return rc;
}
