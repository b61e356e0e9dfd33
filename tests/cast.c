/* cast.c: what the device property tests share (cast.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cast.h"

static uint64_t state = 0x2545f4914f6cdd1dull;

void cast_seed(uint64_t seed)
{
	state = seed;
}

double cast_uniform(void)
{
	uint64_t z = (state += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

void cast_random_unit(double d[3])
{
	double z = 2 * cast_uniform() - 1, a = 2 * M_PI * cast_uniform(), r = sqrt(1 - z * z);
	d[0] = r * cos(a), d[1] = r * sin(a), d[2] = z;
}

int cast_rays(device_ctx *dev, cl_program prog, const char *name, const lower_result *lr, const float *rays, int n,
              float *out, int per_ray, int extra)
{
	cl_int err;
	cl_kernel k = clCreateKernel(prog, name, &err);
	if (!k)
		return device_fail(name, err);
	size_t out_bytes = (size_t)n * per_ray * 4 * sizeof(float);
	cl_mem b[4] = {
		clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lr->dev_node_bytes,
		               (void *)lr->dev_nodes, &err),
		clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lr->n_all_prims * sizeof(dev_prim),
		               lr->prims, &err),
		clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, (size_t)n * 8 * sizeof(float),
		               (void *)rays, &err),
		clCreateBuffer(dev->context, CL_MEM_WRITE_ONLY, out_bytes, NULL, &err),
	};
	clSetKernelArg(k, 0, sizeof(cl_mem), &b[0]);
	clSetKernelArg(k, 1, sizeof(cl_mem), &b[1]);
	clSetKernelArg(k, 2, sizeof(int), &lr->n_prims);
	clSetKernelArg(k, 3, sizeof(int), &lr->n_planes);
	clSetKernelArg(k, 4, sizeof(cl_mem), &b[2]);
	clSetKernelArg(k, 5, sizeof(cl_mem), &b[3]);
	if (extra >= 0)
		clSetKernelArg(k, 6, sizeof(int), &extra);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(dev->queue, b[3], CL_TRUE, 0, out_bytes, out, 0, NULL, NULL);
	for (int i = 0; i < 4; i++)
		clReleaseMemObject(b[i]);
	clReleaseKernel(k);
	return err == CL_SUCCESS ? 0 : device_fail(name, err);
}

double cast_trace_from(const cast_shape *sh, const double wo[3], const double wd[3], double tmin, double n[3])
{
	double o[3], d[3];
	scene_xform_point(&sh->inv, wo, o);
	scene_xform_vector(&sh->inv, wd, d);
	shape_hit h = { .t = INFINITY };
	shape_of(sh->o)->trace(sh->s, sh->o, o, d, tmin, &h);
	if (n)
		memcpy(n, h.n, sizeof h.n);
	return h.t;
}

double cast_trace(const cast_shape *sh, const double wo[3], const double wd[3], double n[3])
{
	return cast_trace_from(sh, wo, wd, 0, n);
}

int cast_check_inside(const cast_shape *sh, const char *what, const double lo[3], const double hi[3], double size,
                      int n)
{
	int bad = 0, bad_normal = 0, inside = 0;
	for (int i = 0; i < n; i++) {
		double p[3], d[3], op[3], od[3], q[3];
		for (int k = 0; k < 3; k++)
			p[k] = lo[k] + cast_uniform() * (hi[k] - lo[k]);
		cast_random_unit(d);
		scene_xform_point(&sh->inv, p, op);
		bool in = shape_of(sh->o)->inside(sh->s, sh->o, op);
		inside += in;
		int crossings = 0;
		memcpy(q, p, sizeof q);
		for (int c = 0; c < 200; c++) {
			double nrm[3], t = cast_trace(sh, q, d, nrm);
			if (isinf(t))
				break;
			scene_xform_vector(&sh->inv, d, od);
			double dot = nrm[0] * od[0] + nrm[1] * od[1] + nrm[2] * od[2];
			/* leaving the solid (odd crossings so far from inside) faces out */
			bool leaving = (crossings % 2 == 0) == in;
			bad_normal += dot != 0 && (dot > 0) != leaving;
			crossings++;
			for (int k = 0; k < 3; k++)
				q[k] += t * d[k];
			for (int k = 0; k < 3; k++)
				q[k] += 1e-9 * size * d[k];
		}
		bad += (crossings % 2 == 1) != in;
	}
	bool ok = bad <= 4 && bad_normal <= 4;
	printf("%s: %s: %d points (%d inside), %d disagree with trace()'s crossings, %d normals face in\n",
	       ok ? "ok" : "FAIL", what, n, inside, bad, bad_normal);
	return ok ? 0 : -1;
}
