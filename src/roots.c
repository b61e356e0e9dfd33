/* roots.c: the real roots of a polynomial, isolated between the roots of its
 * derivatives. Between two neighbouring roots of p' the polynomial p is
 * monotonic, so it has a root there exactly when its values at the two ends
 * differ in sign, and bisection with Newton's steps finds it. The roots of p'
 * come the same way from those of p'', down to a linear derivative, so the
 * search runs upwards: the (n-1)-th derivative first, then each derivative
 * between the roots of the one above it. No root that crosses zero is lost,
 * however close it is to another (a ray grazing a surface), which closed
 * formulas (Ferrari's quartic) and POV-Ray's non-Sturm solvers do not promise.
 *
 * kernels/roots.cl is the same code for the device; keep them in step. */
#include <float.h>
#include <math.h>

#include "roots.h"

#define REFINE_STEPS 200   /* bisection where Newton creeps: 1e30 to a double's ulp */

/* c[0] + ... + c[n] x^n, and its derivative into *dp. */
static double value(const double *c, int n, double x, double *dp)
{
	double v = c[n], d = 0;
	for (int i = n - 1; i >= 0; i--) {
		d = d * x + v;
		v = v * x + c[i];
	}
	*dp = d;
	return v;
}

/* The root in [lo, hi] of c, whose value flo at lo has the other sign than at
 * hi: bisection, with Newton's steps where they stay in the bracket and
 * shrink it fast enough. */
static double refine(const double *c, int n, double lo, double hi, double flo)
{
	double x = 0.5 * (lo + hi), dx = hi - lo, dxold = dx;
	for (int i = 0; i < REFINE_STEPS; i++) {
		double df, f = value(c, n, x, &df);
		if (f == 0)
			return x;
		if ((f < 0) == (flo < 0))
			lo = x, flo = f;
		else
			hi = x;
		/* Newton's step, unless it leaves the bracket or is more than half
		 * the step before: near a cluster of roots it creeps (rtsafe) */
		double next = x - f / df;
		dxold = dx;
		dx = f / df;
		if (!(next > lo && next < hi) || fabs(2 * f) > fabs(dxold * df)) {
			dx = 0.5 * (hi - lo);
			next = lo + dx;
		}
		if (next == x || hi - lo <= 4 * DBL_EPSILON * fmax(fabs(lo), fabs(hi)))
			return next;
		x = next;
	}
	return x;
}

/* The roots of c between the breakpoints ends[0] < ... < ends[m - 1], where it
 * is monotonic: at most max, into out. */
static int between(const double *c, int n, const double *ends, int m, double *out, int max)
{
	int k = 0;
	double d, flo = value(c, n, ends[0], &d);
	for (int i = 1; i < m && k < max; i++) {
		double fhi = value(c, n, ends[i], &d);
		if (fhi == 0)
			out[k++] = ends[i];
		else if (flo != 0 && (flo < 0) != (fhi < 0))
			out[k++] = refine(c, n, ends[i - 1], ends[i], flo);
		flo = fhi;
	}
	return k;
}

int roots_find(const double *c, int n, double a, double b, double *out, int max)
{
	while (n > 0 && c[n] == 0)
		n--;
	if (n <= 0 || n > ROOTS_MAX_ORDER)
		return 0;
	/* Cauchy's bound: every root, and so every derivative's, is within R */
	double R = 0;
	for (int i = 0; i < n; i++)
		R = fmax(R, fabs(c[i] / c[n]));
	a = fmax(a, -(1 + R));
	b = fmin(b, 1 + R);
	if (!(a < b))
		return 0;
	double d[ROOTS_MAX_ORDER + 1], ends[ROOTS_MAX_ORDER + 2], found[ROOTS_MAX_ORDER + 1];
	int nf = 0;
	for (int k = 1; k <= n; k++) {
		/* the (n-k)-th derivative over (n-k)!: degree k, c[i+s] C(i+s, s) */
		int s = n - k;
		double binom = 1;
		for (int i = 0; i <= k; i++) {
			if (i > 0)
				binom = binom * (i + s) / i;
			d[i] = c[i + s] * binom;
		}
		int m = 0;
		ends[m++] = a;
		for (int i = 0; i < nf; i++)
			if (found[i] > ends[m - 1] && found[i] < b)
				ends[m++] = found[i];
		ends[m++] = b;
		if (k == n)
			return between(d, k, ends, m, out, max);
		nf = between(d, k, ends, m, found, k);
	}
	return 0;
}
