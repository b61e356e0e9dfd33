/* vec3.h: the double-precision vector helpers the host's stages share (the
 * kernels have OpenCL's own). */
#ifndef ECLAT_VEC3_H
#define ECLAT_VEC3_H

#include <math.h>

static inline double vec3_dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* a x b into out, which may be a or b. */
static inline void vec3_cross(const double a[3], const double b[3], double out[3])
{
	double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
	out[0] = c[0];
	out[1] = c[1];
	out[2] = c[2];
}

/* v at length 1; a zero vector stays as it is. */
static inline void vec3_normalize(double v[3])
{
	double l = sqrt(vec3_dot(v, v));
	for (int k = 0; k < 3 && l > 0; k++)
		v[k] /= l;
}

#endif
