/* shape_poly.cl: POV-Ray's polynomial surfaces (poly, cubic, quartic,
 * polynomial; src/shape_poly.c says how they are read and solved), kept as the
 * map from world space to the poly's own, its order in its first record and
 * its coefficients, in POV-Ray's order, two in each record after it: each as
 * a float and the float of what it leaves, added here in `real`. Every step is
 * the host's trace() in `real`, with kernels/roots.cl for src/roots.c. */

#define POLY_DEPTH_TOLERANCE 1e-4f    /* POV-Ray's: nearer hits (in the poly's space) are skipped */
#define POLY_INSIDE_TOLERANCE 1e-4f   /* POV-Ray's: a value below it is inside */
#define POLY_MAX_DISTANCE 1e7f        /* POV-Ray's: its solver looks no further */

static inline int poly_order(global const dev_prim *prims, global const dev_prim *p)
{
	return (int)intersect_data(prims, p).x;
}

/* Its bound (SCENE_BOUND_ in src/scene.h: 0 none, 1 the unit sphere, 2 the
 * cube [-1, 1]^3), whose map from the poly's space is in the three records
 * after the first. */
static inline int poly_bound(global const dev_prim *prims, global const dev_prim *p)
{
	return (int)intersect_data(prims, p).y;
}

/* Coefficient i, from its two floats, after the bound's records. */
static inline real poly_coeff(global const dev_prim *prims, global const dev_prim *p, int i)
{
	float4 r = prims[p->link + (poly_bound(prims, p) ? 4 : 1) + i / 2].a;
	return (i & 1) ? (real)r.z + (real)r.w : (real)r.x + (real)r.y;
}

/* acc = acc (p + d s) + add, polynomials in s of degrees *deg and adeg (-1:
 * zero), and the same with every number's size, which bounds the rounding. */
static inline void poly_horner_step(real *acc, real *mag, int *deg, real p, real d, const real *add, const real *amag,
                             int adeg)
{
	int n = *deg;
	if (n >= 0) {
		acc[n + 1] = acc[n] * d;
		mag[n + 1] = mag[n] * fabs(d);
		for (int h = n; h >= 1; h--) {
			acc[h] = acc[h] * p + acc[h - 1] * d;
			mag[h] = mag[h] * fabs(p) + mag[h - 1] * fabs(d);
		}
		acc[0] *= p;
		mag[0] *= fabs(p);
		n++;
	}
	for (int h = n + 1; h <= adeg; h++)
		acc[h] = mag[h] = (real)0;
	for (int h = 0; h <= adeg; h++) {
		acc[h] += add[h];
		mag[h] += amag[h];
	}
	*deg = n > adeg ? n : adeg;
}

/* The polynomial along the ray P + s D into q (q[h] of s^h); its degree, the
 * leading coefficients lost in rounding dropped. */
static inline int poly_along(global const dev_prim *prims, global const dev_prim *p, int n, real3 P, real3 D, real *q)
{
	real mx[ROOTS_MAX_ORDER + 1], ay[ROOTS_MAX_ORDER + 1], my[ROOTS_MAX_ORDER + 1];
	real az[ROOTS_MAX_ORDER + 1], mz[ROOTS_MAX_ORDER + 1];
	int term = 0, dx = -1;
	for (int i = n; i >= 0; i--) {
		int dy = -1;
		for (int j = n - i; j >= 0; j--) {
			int dz = -1;
			for (int k = n - i - j; k >= 0; k--) {
				real c = poly_coeff(prims, p, term++), m = fabs(c);
				poly_horner_step(az, mz, &dz, P.z, D.z, &c, &m, 0);
			}
			poly_horner_step(ay, my, &dy, P.y, D.y, az, mz, dz);
		}
		poly_horner_step(q, mx, &dx, P.x, D.x, ay, my, dy);
	}
	while (dx > 0 && fabs(q[dx]) <= (real)(8 * (n + 1)) * REAL_EPSILON * mx[dx])
		dx--;
	return dx;
}

/* POV-Ray's Ray_In_Bound: whether the ray (P, D) in the poly's space meets
 * its bound ahead of P, or starts inside it. */
static inline bool poly_ray_in_bound(global const dev_prim *prims, global const dev_prim *p, int kind, real3 P, real3 D)
{
	float4 a = prims[p->link + 1].a, b = prims[p->link + 2].a, c = prims[p->link + 3].a;
	real3 ra = convert_real3(a.xyz), rb = convert_real3(b.xyz), rc = convert_real3(c.xyz);
	real3 bp = (real3)(dot(ra, P) + (real)a.w, dot(rb, P) + (real)b.w, dot(rc, P) + (real)c.w);
	real3 bd = (real3)(dot(ra, D), dot(rb, D), dot(rc, D));
	if (kind == 1) {
		real pp = dot(bp, bp), pd = dot(bp, bd);
		return pp <= (real)1 || (pd < (real)0 && pd * pd - dot(bd, bd) * (pp - (real)1) >= (real)0);
	}
	real near = -INFINITY, far = INFINITY;
	for (int k = 0; k < 3; k++) {
		real pk = k == 0 ? bp.x : k == 1 ? bp.y : bp.z, dk = k == 0 ? bd.x : k == 1 ? bd.y : bd.z;
		if (dk == (real)0) {
			if (fabs(pk) > (real)1)
				return false;
			continue;
		}
		real t0 = ((real)-1 - pk) / dk, t1 = ((real)1 - pk) / dk;
		near = fmax(near, fmin(t0, t1));
		far = fmin(far, fmax(t0, t1));
	}
	return near <= far && far >= (real)0;
}

static inline float poly_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p, float tmin,
                            float tmax)
{
	int n = poly_order(prims, p), kind = poly_bound(prims, p);
	if (n < 1 || n > ROOTS_MAX_ORDER)
		return tmax;
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	real len = length(D);
	if (!(len > (real)0))
		return tmax;
	if (kind != 0 && !poly_ray_in_bound(prims, p, kind, P, D))
		return tmax;
	D /= len;
	/* about the ray's point nearest the poly's origin (src/shape_poly.c) */
	real b = -dot(P, D), q[ROOTS_MAX_ORDER + 1], u;
	int deg = poly_along(prims, p, n, P + b * D, D, q);
	real lo = fmax((real)tmin * len, (real)POLY_DEPTH_TOLERANCE) - b;
	real hi = fmin((real)tmax * len, (real)POLY_MAX_DISTANCE) - b;
	/* the first root whose float is past tmin: a root rounded down onto
	 * tmin is the one a CSG's last step stopped at */
	for (int i = 0; i < deg && roots_find(q, deg, lo, hi, &u, 1) == 1; i++) {
		float t = (float)((u + b) / len);
		if (t > tmin)
			return t < tmax ? t : tmax;
		lo = u;
	}
	return tmax;
}

/* The polynomial's value at x (its own space), by Horner's rule in z, y, x. */
static inline real poly_value(global const dev_prim *prims, global const dev_prim *p, int n, real3 x)
{
	int term = 0;
	real vx = 0;
	for (int i = n; i >= 0; i--) {
		real vy = 0;
		for (int j = n - i; j >= 0; j--) {
			real vz = 0;
			for (int k = n - i - j; k >= 0; k--)
				vz = vz * x.z + poly_coeff(prims, p, term++);
			vy = vy * x.y + vz;
		}
		vx = vx * x.x + vy;
	}
	return vx;
}

/* The gradient, POV-Ray's normal; (1, 0, 0) in the poly's space where it vanishes. */
static inline float3 poly_normal(global const dev_prim *prims, global const dev_prim *p, float3 wx)
{
	int n = poly_order(prims, p), term = 0;
	real3 x = intersect_to_local_real(p, wx);
	real px[ROOTS_MAX_ORDER + 1], py[ROOTS_MAX_ORDER + 1], pz[ROOTS_MAX_ORDER + 1];
	px[0] = py[0] = pz[0] = (real)1;
	for (int i = 1; i <= n; i++) {
		px[i] = px[i - 1] * x.x;
		py[i] = py[i - 1] * x.y;
		pz[i] = pz[i - 1] * x.z;
	}
	real3 g = (real3)(0);
	for (int i = n; i >= 0; i--)
		for (int j = n - i; j >= 0; j--)
			for (int k = n - i - j; k >= 0; k--) {
				real c = poly_coeff(prims, p, term++);
				if (c == (real)0)
					continue;
				if (i > 0)
					g.x += (real)i * c * px[i - 1] * py[j] * pz[k];
				if (j > 0)
					g.y += (real)j * c * px[i] * py[j - 1] * pz[k];
				if (k > 0)
					g.z += (real)k * c * px[i] * py[j] * pz[k - 1];
			}
	float3 gf = (float3)((float)g.x, (float)g.y, (float)g.z);
	if (gf.x == 0.0f && gf.y == 0.0f && gf.z == 0.0f)
		gf = (float3)(1.0f, 0.0f, 0.0f);
	return intersect_normal_to_world(p, gf);
}

static inline bool poly_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return poly_value(prims, p, poly_order(prims, p), intersect_to_local_real(p, x)) < (real)POLY_INSIDE_TOLERANCE;
}
