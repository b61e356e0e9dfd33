/* shape_torus.cl: POV-Ray's torus, kept as the map from world space to the
 * torus of major radius 1 around the y axis, the minor radius k (the minor
 * over the major) in its PRIM_DATA record. A minor radius above the major is
 * POV-Ray 3.7's spindle torus: every root is a surface (src/shape_torus.c).
 *
 * The ray's roots are those of a quartic. Float loses them at grazing rays,
 * and a closed formula (Ferrari's) loses them to cancellation, so the quartic
 * is solved in double where the device has it, between the roots of its
 * derivative, where it is monotonic: those of the cubic derivative are found
 * between the roots of the quadratic second derivative in the same way. */

/* c[0] + c[1] x + ... + c[n] x^n, and its derivative into *dp. */
inline real torus_poly(const real *c, int n, real x, real *dp)
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
 * hi: bisection, with Newton's steps where they stay in the bracket. */
inline real torus_refine(const real *c, int n, real lo, real hi, real flo)
{
	real x = (real)0.5 * (lo + hi);
	for (int i = 0; i < 80; i++) {
		real df, f = torus_poly(c, n, x, &df);
		if (f == (real)0)
			return x;
		if ((f < (real)0) == (flo < (real)0)) {
			lo = x;
			flo = f;
		} else {
			hi = x;
		}
		real next = x - f / df;
		if (!(next > lo && next < hi))
			next = (real)0.5 * (lo + hi);
		if (next == x || hi - lo <= (real)4 * REAL_EPSILON * fmax(fabs(lo), fabs(hi)))
			return next;
		x = next;
	}
	return x;
}

/* The roots in (0, len] of c (degree n, 3 or 4) between the breakpoints
 * ends[0] = 0 < ends[1] < ... < ends[m - 1] = len, where it is monotonic: up
 * to max of them, in increasing order, into out. */
inline int torus_roots(const real *c, int n, const real *ends, int m, real *out, int max)
{
	int k = 0;
	real d, flo = torus_poly(c, n, ends[0], &d);
	for (int i = 1; i < m && k < max; i++) {
		real fhi = torus_poly(c, n, ends[i], &d);
		if (fhi == (real)0)
			out[k++] = ends[i];
		else if (flo != (real)0 && (flo < (real)0) != (fhi < (real)0))
			out[k++] = torus_refine(c, n, ends[i - 1], ends[i], flo);
		flo = fhi;
	}
	return k;
}

inline float torus_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                             float tmin, float tmax)
{
	real k = intersect_data(prims, p).x;
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	real len = length(D);
	if (!(len > (real)0))
		return tmax;
	D /= len;
	/* the bounding sphere: the chord from the point nearest the centre, for
	 * precision; the quartic in the distance from where the ray enters it */
	real B = ((real)1 + k) * (real)(1 + 1e-6), b = dot(P, D);
	real3 f = P - b * D;
	real disc = B * B - dot(f, f);
	if (disc < (real)0)
		return tmax;
	real h = sqrt(disc);
	real s0 = fmax(-b - h, (real)tmin * len), s1 = fmin(-b + h, (real)tmax * len);
	if (!(s0 < s1))
		return tmax;
	P += s0 * D;
	real L = s1 - s0, k2 = k * k, Py = P.y, Dy = D.y;
	real k1 = dot(P, P) - (real)1 - k2, pd = dot(P, D);
	real c[5] = { k1 * k1 + (real)4 * (Py * Py - k2), (real)4 * (pd * k1 + (real)2 * Py * Dy),
	              (real)2 * (k1 + (real)2 * (pd * pd + Dy * Dy)), (real)4 * pd, (real)1 };
	/* the second derivative's roots (a quadratic), where the first turns */
	real ends[6], crit[3], d1[4] = { c[1], (real)2 * c[2], (real)3 * c[3], (real)4 };
	int m = 0;
	ends[m++] = (real)0;
	real qa = (real)12, qb = (real)6 * c[3], qc = (real)2 * c[2], qd = qb * qb - (real)4 * qa * qc;
	if (qd > (real)0) {
		real q = (real)-0.5 * (qb + (qb < (real)0 ? -sqrt(qd) : sqrt(qd)));
		real r0 = q / qa, r1 = q != (real)0 ? qc / q : r0;
		real lo = fmin(r0, r1), hi = fmax(r0, r1);
		if (lo > (real)0 && lo < L)
			ends[m++] = lo;
		if (hi > (real)0 && hi < L && hi > ends[m - 1])
			ends[m++] = hi;
	}
	ends[m++] = L;
	/* the first derivative's roots (a cubic), where the quartic turns */
	int nc = torus_roots(d1, 3, ends, m, crit, 3);
	m = 0;
	ends[m++] = (real)0;
	for (int i = 0; i < nc; i++)
		if (crit[i] > ends[m - 1] && crit[i] < L)
			ends[m++] = crit[i];
	ends[m++] = L;
	real u;
	if (torus_roots(c, 4, ends, m, &u, 1) == 0)
		return tmax;
	float t = (float)((s0 + u) / len);
	return t > tmin && t < tmax ? t : tmax;
}

/* The geometric normal, the quartic's gradient: from the nearest point M of
 * the circle, P - M, or on a spindle torus's inner surface (inside the sphere
 * through the spindle's tips), where the tube around the far point -M makes
 * the surface, -(P + M). */
inline float3 torus_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float k = intersect_data(prims, p).x;
	float3 q = intersect_to_local(p, x);
	float rho = sqrt(q.x * q.x + q.z * q.z);
	float3 m = rho > 1e-10f ? (float3)(q.x / rho, 0.0f, q.z / rho) : (float3)(0.0f);
	return intersect_normal_to_world(p, dot(q, q) < k * k - 1.0f ? -(q + m) : q - m);
}

/* POV-Ray's normal, P - M everywhere: the shading normal (shape.cl). It is
 * not the spindle's, which is why rays that leave the surface are moved off
 * it along the geometric one. */
inline float3 torus_shading_normal(global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float rho = sqrt(q.x * q.x + q.z * q.z);
	float3 m = rho > 1e-10f ? (float3)(q.x / rho, 0.0f, q.z / rho) : (float3)(0.0f);
	return intersect_normal_to_world(p, q - m);
}

inline bool torus_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float k = intersect_data(prims, p).x;
	float3 q = intersect_to_local(p, x);
	float r = sqrt(q.x * q.x + q.z * q.z) - 1.0f;
	return r * r + q.y * q.y <= k * k;
}
