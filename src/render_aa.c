/* render_aa.c: the Whitted integrator's anti-aliasing (+A, POV-Ray's methods 1
 * and 2) as one pass of two kernels (kernels/whitted_pixel.cl): a trace per
 * point of a grid into a scratch buffer, then the supersampling, which writes
 * the film. The kernels take the render kernels' buffers, then the scratch
 * buffer, the rows and the settings. */
#include <stdlib.h>

#include "render.h"

#define AA_GROUP 16      /* as the Whitted kernel's: private stacks stay small on PoCL */

static size_t round_up(size_t n)
{
	return (n + AA_GROUP - 1) / AA_GROUP * AA_GROUP;
}

static cl_int run(device_ctx *d, cl_kernel k, const cl_mem *bufs, int n_bufs, cl_mem scratch, int first_row,
                  int rows, const void *last, size_t last_size, size_t items)
{
	cl_int err = CL_SUCCESS;
	for (int i = 0; i < n_bufs && err == CL_SUCCESS; i++)
		err = clSetKernelArg(k, i, sizeof(cl_mem), &bufs[i]);
	if (err == CL_SUCCESS)
		err = clSetKernelArg(k, n_bufs, sizeof scratch, &scratch);
	if (err == CL_SUCCESS)
		err = clSetKernelArg(k, n_bufs + 1, sizeof first_row, &first_row);
	if (err == CL_SUCCESS)
		err = clSetKernelArg(k, n_bufs + 2, sizeof rows, &rows);
	if (err == CL_SUCCESS)
		err = clSetKernelArg(k, n_bufs + 3, last_size, last);
	size_t local = AA_GROUP, global = round_up(items);
	if (err == CL_SUCCESS)
		err = clEnqueueNDRangeKernel(d->queue, k, 1, NULL, &global, &local, 0, NULL, NULL);
	return err == CL_SUCCESS ? clFinish(d->queue) : err;
}

int render_aa_pass(device_ctx *d, cl_program prog, const cl_mem *bufs, int n_bufs, const render_settings *rs)
{
	int first_row = rs->rows ? rs->row_first : 0, rows = rs->rows ? rs->rows : rs->height;
	size_t grid = (size_t)(rs->width + 1) * (rows + 1), pixels = (size_t)rs->width * rows;
	/* method 1 keeps each pixel's colour and flag after the grid */
	size_t bytes = (grid + (rs->aa_method == 1 ? 2 * pixels : 0)) * sizeof(cl_float4);
	cl_int err;
	cl_kernel k_grid = clCreateKernel(prog, "whitted_aa_grid", &err), k_aa = NULL;
	if (k_grid)
		k_aa = clCreateKernel(prog, rs->aa_method == 1 ? "whitted_aa_m1" : "whitted_aa_m2", &err);
	if (!k_aa) {
		if (k_grid)
			clReleaseKernel(k_grid);
		return device_fail("clCreateKernel", err);
	}
	const char *what = "clCreateBuffer";
	cl_mem scratch = clCreateBuffer(d->context, CL_MEM_READ_WRITE, bytes, NULL, &err);
	if (scratch) {
		what = "clEnqueueNDRangeKernel";
		float zero = 0;
		err = clEnqueueFillBuffer(d->queue, scratch, &zero, sizeof zero, 0, bytes, 0, NULL, NULL);
	}
	cl_int method = rs->aa_method;
	/* POV-Ray divides the jitter by the samples across a pixel: +R for method
	 * 1, 2^R + 1 for method 2 */
	float across = rs->aa_method == 1 ? (float)rs->aa_depth : (float)((1 << rs->aa_depth) + 1);
	cl_float4 aa = { .s = { rs->aa_threshold, (float)rs->aa_depth, rs->aa_jitter / across, rs->aa_gamma } };
	if (scratch && err == CL_SUCCESS)
		err = run(d, k_grid, bufs, n_bufs, scratch, first_row, rows, &method, sizeof method, grid);
	if (scratch && err == CL_SUCCESS) {
		size_t blocks = (size_t)((rs->width + RENDER_AA_BLOCK - 1) / RENDER_AA_BLOCK) *
		                ((rows + RENDER_AA_BLOCK - 1) / RENDER_AA_BLOCK);
		err = run(d, k_aa, bufs, n_bufs, scratch, first_row, rows, &aa, sizeof aa,
		          rs->aa_method == 1 ? blocks : pixels);
	}
	if (scratch)
		clReleaseMemObject(scratch);
	clReleaseKernel(k_grid);
	clReleaseKernel(k_aa);
	return err == CL_SUCCESS ? 0 : device_fail(what, err);
}
