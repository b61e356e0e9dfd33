/* cast.h: what the device property tests share (test_csg, test_prism,
 * test_revolve, test_torus): their random numbers, rays cast through a
 * kernel of kernels/raycast.cl, and a shape's own trace() in world space, the
 * host's double-precision answer the device is held to. */
#ifndef ECLAT_TESTS_CAST_H
#define ECLAT_TESTS_CAST_H

#include <stdint.h>

#include "device.h"
#include "lower.h"
#include "shape.h"

/* splitmix64: uniform in [0, 1); cast_seed starts a test's own sequence. */
void cast_seed(uint64_t seed);
double cast_uniform(void);
void cast_random_unit(double d[3]);

/* Casts n rays (two float4 each: the origin with tmax in w, the direction)
 * through the kernel `name` (raycast, or shapecast with its shape argument
 * extra >= 0), which writes per_ray float4s a ray into out. 0, or -1 after
 * printing the OpenCL error. */
int cast_rays(device_ctx *dev, cl_program prog, const char *name, const lower_result *lr, const float *rays, int n,
              float *out, int per_ray, int extra);

/* A shape of a scene and the inverse of its transform. */
typedef struct {
	const scene *s;
	const scene_object *o;
	xform inv;
} cast_shape;

/* The shape's nearest hit of the world ray after tmin, by its class's trace()
 * in object space (the parameter is the same in both spaces): t, or INFINITY;
 * n (when not NULL) gets the object-space normal. */
double cast_trace_from(const cast_shape *sh, const double wo[3], const double wd[3], double tmin, double n[3]);
double cast_trace(const cast_shape *sh, const double wo[3], const double wd[3], double n[3]);

/* The host's inside test against trace(): n random points of [lo, hi] (world
 * space; size the shape's), each inside when a ray out of it crosses the
 * surface an odd number of times, and every crossing's normal facing out.
 * Prints one ok/FAIL line; 0, or -1 when more than 4 points or normals are
 * wrong. */
int cast_check_inside(const cast_shape *sh, const char *what, const double lo[3], const double hi[3], double size,
                      int n);

#endif
