/* roots.cl: the real roots of a polynomial in `real` (double where the device
 * has it), isolated between the roots of its derivatives: the device's twin of
 * src/roots.c, which says why; keep them in step. The torus and poly shapes
 * solve their rays with it. */

#define ROOTS_MAX_ORDER 35
#define ROOTS_REFINE_STEPS 200

/* c[0] + ... + c[n] x^n, and its derivative into *dp. */
static inline real roots_value(const real *c, int n, real x, real *dp)
{
	real v = c[n], d = 0;
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
static inline real roots_refine(const real *c, int n, real lo, real hi, real flo)
{
	real x = (real)0.5 * (lo + hi), dx = hi - lo, dxold = dx;
	for (int i = 0; i < ROOTS_REFINE_STEPS; i++) {
		real df, f = roots_value(c, n, x, &df);
		if (f == (real)0)
			return x;
		if ((f < (real)0) == (flo < (real)0)) {
			lo = x;
			flo = f;
		} else {
			hi = x;
		}
		/* Newton's step, unless it leaves the bracket or is more than half
		 * the step before: near a cluster of roots it creeps (rtsafe) */
		real next = x - f / df;
		dxold = dx;
		dx = f / df;
		if (!(next > lo && next < hi) || fabs((real)2 * f) > fabs(dxold * df)) {
			dx = (real)0.5 * (hi - lo);
			next = lo + dx;
		}
		if (next == x || hi - lo <= (real)4 * REAL_EPSILON * fmax(fabs(lo), fabs(hi)))
			return next;
		x = next;
	}
	return x;
}

/* The roots of c between the breakpoints ends[0] < ... < ends[m - 1], where it
 * is monotonic: at most max, into out. */
static inline int roots_between(const real *c, int n, const real *ends, int m, real *out, int max)
{
	int k = 0;
	real d, flo = roots_value(c, n, ends[0], &d);
	for (int i = 1; i < m && k < max; i++) {
		real fhi = roots_value(c, n, ends[i], &d);
		if (fhi == (real)0)
			out[k++] = ends[i];
		else if (flo != (real)0 && (flo < (real)0) != (fhi < (real)0))
			out[k++] = roots_refine(c, n, ends[i - 1], ends[i], flo);
		flo = fhi;
	}
	return k;
}

/* The roots in (a, b] of c[0] + ... + c[n] x^n (leading zeros dropped), in
 * increasing order, at most max of them, into out; returns how many. */
static inline int roots_find(const real *c, int n, real a, real b, real *out, int max)
{
	while (n > 0 && c[n] == (real)0)
		n--;
	if (n <= 0 || n > ROOTS_MAX_ORDER)
		return 0;
	real R = 0;   /* Cauchy's bound: every root, and every derivative's, is within it */
	for (int i = 0; i < n; i++)
		R = fmax(R, fabs(c[i] / c[n]));
	a = fmax(a, -((real)1 + R));
	b = fmin(b, (real)1 + R);
	if (!(a < b))
		return 0;
	real d[ROOTS_MAX_ORDER + 1], ends[ROOTS_MAX_ORDER + 2], found[ROOTS_MAX_ORDER + 1];
	int nf = 0;
	for (int k = 1; k <= n; k++) {
		/* the (n-k)-th derivative over (n-k)!: degree k, c[i+s] C(i+s, s) */
		int s = n - k;
		real binom = 1;
		for (int i = 0; i <= k; i++) {
			if (i > 0)
				binom = binom * (real)(i + s) / (real)i;
			d[i] = c[i + s] * binom;
		}
		int m = 0;
		ends[m++] = a;
		for (int i = 0; i < nf; i++)
			if (found[i] > ends[m - 1] && found[i] < b)
				ends[m++] = found[i];
		ends[m++] = b;
		if (k == n)
			return roots_between(d, k, ends, m, out, max);
		nf = roots_between(d, k, ends, m, found, k);
	}
	return 0;
}
