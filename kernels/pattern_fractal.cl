/* pattern_fractal.cl: POV-Ray 3.7's fractal patterns, mandel, julia and
 * magnet (pattern.cpp's MandelPattern, JuliaPattern, MagnetPattern and their
 * ExteriorColour and InteriorColour), on the point's x and y.
 *
 * The iteration runs in real (double where the device has it) as POV-Ray's
 * does in double: near the set's edge a point's escape count depends on every
 * bit, and float would move the edge by a pixel. The parameters
 * (dev_pattern.params, kernels/shared.h): params[0].x the iteration limit,
 * .y the exponent (mandel, julia) or magnet's type (1 or 2, plus 2 in the
 * julia form), .zw the julia constant; params[1] the interior type and
 * factor, the exterior type and factor. */

/* The value of a point that escaped after iters iterations at (a, b). */
static inline real fractal_exterior(float4 io, int iters, int max_iter, real a, real b)
{
	real f = (real)io.w;
	switch ((int)io.z) {
	case 0: return f;
	case 1: return (real)iters / (real)max_iter;
	case 2: return a * f;
	case 3: return b * f;
	case 4: return a * a * f;
	case 5: return b * b * f;
	case 6: return sqrt(a * a + b * b) * f;
	/* POV-Ray 3.7.1's cycles of iterations */
	case 7: return f >= 1 ? (real)(iters % (uint)f) / f : 0;
	case 8: return f > 0 ? (real)(iters % (uint)(1 + f)) / f : 0;
	default: return 0;
	}
}

/* The value of a point still bound after the last iteration, at (a, b), the
 * orbit's least squared distance from 0 being mindist2. */
static inline real fractal_interior(float4 io, real a, real b, real mindist2)
{
	real f = (real)io.y;
	switch ((int)io.x) {
	case 0: return f;
	case 1: return sqrt(mindist2) * f;
	case 2: return a * f;
	case 3: return b * f;
	case 4: return a * a * f;
	case 5: return b * b * f;
	case 6: return a * a + b * b * f;   /* sic: POV-Ray scales b^2 alone */
	default: return 0;
	}
}

/* (a + bi)^n for n >= 2: POV-Ray's sums of binomial terms, sign by sign. */
static inline void fractal_power(real a, real b, int n, real *ra, real *rb)
{
	real re = 0, im = 0, c = 1;   /* c: n choose k */
	for (int k = 0; k <= n; k++) {
		real term = c * pown(a, n - k) * pown(b, k);
		real sign = (k & 2) ? -1 : 1;
		if (k & 1)
			im += sign * term;
		else
			re += sign * term;
		c = c * (real)(n - k) / (real)(k + 1);
	}
	*ra = re;
	*rb = im;
}

/* mandel (julia = 0: the point is c, z starts at it) and julia (the constant
 * is c, z starts at the point), exponent n: z = z^n + c until |z|^2 > 4. */
static inline real fractal_mandel_julia(float3 p, float4 pr, float4 io, int julia)
{
	int max_iter = max((int)pr.x, 1), n = (int)pr.y;
	real x = (real)p.x, y = (real)p.y;
	real cr = julia ? (real)pr.z : x, ci = julia ? (real)pr.w : y;
	real a = x, b = y, a2 = a * a, b2 = b * b, mindist2 = a2 + b2;
	for (int col = 0; col < max_iter; col++) {
		if (n == 3) {
			b = 3 * a2 * b - b2 * b + ci;
			a = a2 * a - 3 * a * b2 + cr;
		} else if (n == 4) {
			b = 4 * (a2 * a * b - a * b2 * b) + ci;
			a = a2 * a2 - 6 * a2 * b2 + b2 * b2 + cr;
		} else if (n > 4) {
			real na, nb;
			fractal_power(a, b, n, &na, &nb);
			a = na + cr;
			b = nb + ci;
		} else {
			b = 2 * a * b + ci;
			a = a2 - b2 + cr;
		}
		a2 = a * a;
		b2 = b * b;
		real dist2 = a2 + b2;
		mindist2 = fmin(mindist2, dist2);
		if (dist2 > 4)
			return fractal_exterior(io, col, max_iter, a, b);
	}
	return fractal_interior(io, a, b, mindist2);
}

/* magnet 1 and 2, in the mandel form (c the point, z from 0) or the julia
 * form (c the constant, z from the point): Newton-like maps whose orbits
 * escape past |z|^2 = 10000 or settle at z = 1. */
static inline real fractal_magnet(float3 p, float4 pr, float4 io)
{
	int max_iter = max((int)pr.x, 1), type = (int)pr.y;
	int julia = type > 2;
	if (julia)
		type -= 2;
	real cr = julia ? (real)pr.z : (real)p.x, ci = julia ? (real)pr.w : (real)p.y;
	real a = julia ? (real)p.x : 0, b = julia ? (real)p.y : 0;
	real a2 = a * a, b2 = b * b;
	real mindist2 = julia ? a2 + b2 : 10000;
	real c1r = cr - 1, c2r = cr - 2;
	real c1c2r = c1r * c2r - ci * ci, c1c2i = (c1r + c2r) * ci;
	for (int col = 0; col < max_iter; col++) {
		real t1r, t1i, t2r, t2i;
		if (type == 2) {
			t1r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
			t1i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
			t2r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
			t2i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
		} else {
			t1r = a2 - b2 + cr - 1;
			t1i = 2 * a * b + ci;
			t2r = 2 * a + cr - 2;
			t2i = 2 * b + ci;
		}
		real t = t2r * t2r + t2i * t2i;
		a = (t1r * t2r + t1i * t2i) / t;
		b = (t1i * t2r - t1r * t2i) / t;
		b2 = b * b;
		b = 2 * a * b;
		a = a * a - b2;
		a2 = a * a;
		b2 = b * b;
		real dist2 = a2 + b2;
		mindist2 = fmin(mindist2, dist2);
		if (dist2 > 10000 || (a - 1) * (a - 1) + b2 < 1.0 / 10000)
			return fractal_exterior(io, col, max_iter, a, b);
	}
	return fractal_interior(io, a, b, mindist2);
}

/* The value of a fractal pattern kind at p, before frequency and wave.
 * Exterior values grow large (|z| past 100): POV-Ray wraps v * frequency +
 * phase into [0, 1.00001) in double, and float would keep few of the
 * fraction's digits, so a large value is first wrapped here, in real, by the
 * period that frequency gives it, which leaves pattern_wave's result as it
 * is. */
static float pattern_fractal(int kind, float3 p, float4 pr, float4 io, float frequency)
{
	real v = kind == PATTERN_MAGNET ? fractal_magnet(p, pr, io)
	       : fractal_mandel_julia(p, pr, io, kind == PATTERN_JULIA);
	if (frequency != 0.0f && (v < 0 || v >= 1.00001))
		v = fmod(v, 1.00001 / fabs((real)frequency));
	return (float)v;
}
