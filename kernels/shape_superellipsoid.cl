/* shape_superellipsoid.cl: POV-Ray's superellipsoid, kept as the map from
 * world space to its own, where it fills [-1, 1]^3; its PRIM_DATA record holds
 * POV-Ray's exponents p = 2/E and q = 2/N, each as a float and the float of
 * what that leaves, so that the device sees them in double. The function
 * G(G(|x|, |y|, p), |z|, q) - 1, with G(a, b, p) = (a^p + b^p)^(1/p), is below
 * 0 inside (src/shape_superellipsoid.c).
 *
 * A ray's nearest crossing, in double where the device has it:
 *  - E and N at most 2: G is a norm, so the function is convex along the
 *    whole ray. From outside, Newton's steps from the ray's start stay short
 *    of the first crossing (the function lies above its tangents) and reach
 *    it, or show there is none (the function rises, or its tangent reaches 0
 *    only past the end); from inside there is one crossing, bracketed.
 *  - E and N at least 2: G is concave where x, y and z keep their signs, so
 *    the function is concave along the ray within an octant: the same, the
 *    roles of inside and outside swapped, octant by octant.
 *  - otherwise: within an octant |x|, |y|, |z| are affine along the ray and
 *    the function grows with each, so over a stretch of the ray it lies
 *    between its values at the stretch's smallest and largest |x|, |y|, |z|.
 *    The stretches that may hold the surface are halved, nearest first, down
 *    to 1/2^SE_LEVELS of the octant's stretch, where a sign change brackets
 *    the crossing: no crossing is lost but a pair closer together than that,
 *    which only a ray grazing the surface makes.
 * A whole exponent (E or N 2, 1, 0.5, 0.25, 0.2...) is raised to by
 * multiplying, as POV-Ray does. */

#define SE_LEVELS 10

/* An exponent: p, 1/p, and p when it is a whole number up to 64, else 0. */
typedef struct {
	real p, inv;
	int n;
} se_exp;

static inline se_exp se_exponent(float hi, float lo)
{
	se_exp e;
	e.p = (real)hi + (real)lo;
	e.inv = (real)1 / e.p;
	e.n = e.p == floor(e.p) && e.p <= (real)64 ? (int)e.p : 0;
	return e;
}

/* x^p for x in [0, 1]. */
static inline real se_pow(real x, se_exp e)
{
	if (e.n == 0)
		return pow(x, e.p);
	real r = (real)1, b = x;
	for (int n = e.n; n > 0; n >>= 1) {
		if (n & 1)
			r *= b;
		b *= b;
	}
	return r;
}

/* s^(1/p) for s in [1, 2]. */
static inline real se_root(real s, se_exp e)
{
	return e.n == 1 ? s : e.n == 2 ? sqrt(s) : e.n == 4 ? sqrt(sqrt(s)) : pow(s, e.inv);
}

/* G(a, b, p) for a, b >= 0, from the ratio to the larger, without overflow. */
static inline real se_gauge2(real a, real b, se_exp e)
{
	real hi = fmax(a, b), lo = fmin(a, b);
	if (hi == (real)0)
		return (real)0;
	return hi * se_root((real)1 + se_pow(lo / hi, e), e);
}

static inline real se_gauge(real3 v, se_exp p, se_exp q)
{
	return se_gauge2(se_gauge2(fabs(v.x), fabs(v.y), p), fabs(v.z), q);
}

/* |x|, |y| and |z| at x in the octant of signs oct: where the ray crosses
 * into it, a coordinate that rounding puts across 0 counts as 0 (with an
 * exponent below 1 its power would not be small); a sign 0 takes x's own. */
static inline real3 se_abs(real3 x, real3 oct)
{
	return (real3)(oct.x != (real)0 ? fmax(oct.x * x.x, (real)0) : fabs(x.x),
	               oct.y != (real)0 ? fmax(oct.y * x.y, (real)0) : fabs(x.y),
	               oct.z != (real)0 ? fmax(oct.z * x.z, (real)0) : fabs(x.z));
}

/* The function at o + t d, in the octant oct. */
static inline real se_value(real3 o, real3 d, real t, se_exp p, se_exp q, real3 oct)
{
	real3 a = se_abs(o + t * d, oct);
	return se_gauge2(se_gauge2(a.x, a.y, p), a.z, q) - (real)1;
}

/* G(a, b, p) and its derivatives by a and by b, (a / G)^(p - 1) and
 * (b / G)^(p - 1), for a, b >= 0: two powers. */
static inline real se_gauge2_d(real a, real b, se_exp e, real *da, real *db)
{
	real hi = fmax(a, b);
	if (hi == (real)0) {
		*da = *db = (real)0;
		return (real)0;
	}
	real ra = a / hi, rb = b / hi;
	real A = ra == (real)1 ? (real)1 : se_pow(ra, e), B = rb == (real)1 ? (real)1 : se_pow(rb, e);
	real S = A + B, s = se_root(S, e);
	real edge = e.p > (real)1 ? (real)0 : e.p == (real)1 ? (real)1 : INFINITY;   /* a or b 0 */
	*da = ra > (real)0 ? A * s / (ra * S) : edge;
	*db = rb > (real)0 ? B * s / (rb * S) : edge;
	return hi * s;
}

/* The function at o + t d, and its derivative along the ray into *df, with
 * the signs sg of x, y and z: those of the octant the point is taken in (a
 * coordinate a rounding across 0 counts as 0), or where sg is 0, its own
 * (0: the way the ray goes). */
static inline real se_eval(real3 o, real3 d, real t, se_exp p, se_exp q, real3 sg, real *df)
{
	real3 x = o + t * d;
	real3 s = (real3)(sg.x != (real)0 ? sg.x : x.x != (real)0 ? sign(x.x) : sign(d.x),
	                  sg.y != (real)0 ? sg.y : x.y != (real)0 ? sign(x.y) : sign(d.y),
	                  sg.z != (real)0 ? sg.z : x.z != (real)0 ? sign(x.z) : sign(d.z));
	real3 a = fmax(s * x, (real)0), r = s * d;   /* |x|, |y|, |z| and how fast they grow */
	real g1a, g1b, g2g, g2c;
	real g1 = se_gauge2_d(a.x, a.y, p, &g1a, &g1b);
	real g2 = se_gauge2_d(g1, a.z, q, &g2g, &g2c);
	*df = g2g * (g1a * r.x + g1b * r.y) + g2c * r.z;
	return g2 - (real)1;
}

/* Whether the surface may cross the ray in [t0, t1], a stretch within one octant. */
static inline bool se_may_cross(real3 o, real3 d, real t0, real t1, se_exp p, se_exp q, real3 oct)
{
	real3 a = se_abs(o + t0 * d, oct), b = se_abs(o + t1 * d, oct);
	return se_gauge(fmin(a, b), p, q) <= (real)1 && se_gauge(fmax(a, b), p, q) >= (real)1;
}

/* The crossing in [a, b], where the function changes sign (fa, fb): the
 * Illinois variant of regula falsi. */
static inline real se_bracketed(real3 o, real3 d, se_exp p, se_exp q, real3 oct, real a, real fa, real b, real fb)
{
	real tol = (real)4 * REAL_EPSILON * (fabs(a) + fabs(b)), c = a;
	int side = 0;
	for (int i = 0; i < 60 && b - a > tol; i++) {
		real prev = c;
		c = (a * fb - b * fa) / (fb - fa);
		if (!(c > a && c < b))
			c = (real)0.5 * (a + b);
		real fc = se_value(o, d, c, p, q, oct);
		if (fc == (real)0 || fabs(c - prev) <= tol)
			return c;
		if ((fc < (real)0) == (fb < (real)0)) {
			b = c;
			fb = fc;
			if (side == -1)
				fa *= (real)0.5;
			side = -1;
		} else {
			a = c;
			fa = fc;
			if (side == 1)
				fb *= (real)0.5;
			side = 1;
		}
	}
	return c;
}

/* The nearest crossing in [a, b], a stretch within one octant, or -1: the
 * stretches of a binary tree over it, depth first and nearest first, without
 * a stack (a stretch's index at its level says where it is). */
static inline real se_first_crossing(real3 o, real3 d, se_exp p, se_exp q, real3 oct, real a, real b)
{
	real3 r = oct * d;   /* how fast |x|, |y|, |z| grow */
	if ((r.x >= (real)0 && r.y >= (real)0 && r.z >= (real)0) || (r.x <= (real)0 && r.y <= (real)0 && r.z <= (real)0)) {
		/* all grow, or all shrink: the function is monotonic, one crossing at most */
		real fa = se_value(o, d, a, p, q, oct), fb = se_value(o, d, b, p, q, oct);
		if (fb == (real)0)
			return b;
		return fa != (real)0 && (fa < (real)0) != (fb < (real)0) ? se_bracketed(o, d, p, q, oct, a, fa, b, fb)
		                                                        : (real)-1;
	}
	int level = 0, idx = 0;
	real t0 = a;
	for (;;) {
		real t1 = idx + 1 == 1 << level ? b : a + (b - a) * ((real)(idx + 1) / (real)(1 << level));
		if (se_may_cross(o, d, t0, t1, p, q, oct)) {
			if (level < SE_LEVELS) {
				level++;
				idx *= 2;
				continue;
			}
			real tm = (real)0.5 * (t0 + t1);
			real f0 = se_value(o, d, t0, p, q, oct), fm = se_value(o, d, tm, p, q, oct);
			real f1 = se_value(o, d, t1, p, q, oct);
			if (fm == (real)0)
				return tm;
			if (f0 != (real)0 && (f0 < (real)0) != (fm < (real)0))
				return se_bracketed(o, d, p, q, oct, t0, f0, tm, fm);
			if (f1 == (real)0 || (fm < (real)0) != (f1 < (real)0))
				return f1 == (real)0 ? t1 : se_bracketed(o, d, p, q, oct, tm, fm, t1, f1);
		}
		t0 = t1;
		while (idx & 1) {
			idx >>= 1;
			level--;
		}
		if (level == 0)
			return (real)-1;
		idx++;
	}
}

/* The nearest crossing in [a, b] where the function, sgn times it, is
 * convex, or -1. Where that is above 0, Newton's steps from a stay short of
 * the crossing (the function lies above its tangents); it can rise no more
 * once it rises, and where it is below 0 it crosses once. sgn is 1 for a
 * convex stretch, -1 for a concave one, within the octant of signs oct (0:
 * any). */
static inline real se_newton(real3 o, real3 d, se_exp p, se_exp q, real a, real b, real sgn, real3 oct)
{
	real df, f = se_eval(o, d, a, p, q, oct, &df) * sgn;
	if (f < (real)0) {
		real fb = sgn * se_value(o, d, b, p, q, oct);
		return fb > (real)0 ? se_bracketed(o, d, p, q, oct, a, sgn * f, b, sgn * fb) : (real)-1;
	}
	real t = a, tol = (real)4 * REAL_EPSILON * fmax(fmax(fabs(a), fabs(b)), b - a);
	for (int i = 0; i < 100; i++) {
		df *= sgn;
		if (!(fabs(df) < INFINITY)) {
			/* at an axis plane, where a concave G's slope is infinite: a step in */
			real tn = fmin(t + fmax((real)1e-7 * (b - a), (real)4 * REAL_EPSILON * fabs(t)), b);
			real fn = sgn * se_eval(o, d, tn, p, q, oct, &df);
			if (fn <= (real)0)
				return fn == (real)0 ? tn : se_bracketed(o, d, p, q, oct, t, sgn * f, tn, sgn * fn);
			if (tn == b)
				return (real)-1;
			t = tn;
			f = fn;
			continue;
		}
		if (df >= (real)0)
			return (real)-1;
		real tn = t - f / df;
		if (!(tn <= b))
			return (real)-1;
		if (tn - t <= tol)
			return tn;
		t = tn;
		f = sgn * se_eval(o, d, t, p, q, oct, &df);
		if (f <= (real)0)
			return t;
	}
	return (real)-1;
}

static inline float superellipsoid_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                      float tmin, float tmax)
{
	float4 ex = intersect_data(prims, p);
	se_exp pe = se_exponent(ex.x, ex.y), qe = se_exponent(ex.z, ex.w);
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	/* the cube around it, a little larger */
	real3 inv = (real)1 / D, lim = (real3)((real)(1 + 1e-6));
	real3 ta3 = (-lim - P) * inv, tb3 = (lim - P) * inv;
	real3 lo = fmin(ta3, tb3), hi = fmax(ta3, tb3);
	real ta = fmax(fmax((real)tmin, lo.x), fmax(lo.y, lo.z));
	real tb = fmin(fmin((real)tmax, hi.x), fmin(hi.y, hi.z));
	if (!(ta < tb))
		return tmax;
	if (pe.p >= (real)1 && qe.p >= (real)1) {   /* convex */
		real t = se_newton(P, D, pe, qe, ta, tb, (real)1, (real3)((real)0));
		float ft = (float)t;
		return t >= (real)0 && ft > tmin && ft < tmax ? ft : tmax;
	}
	bool concave = pe.p <= (real)1 && qe.p <= (real)1;
	/* the octants it crosses, in order */
	real3 tc = -P * inv;
	real cut[5];
	int n = 0;
	cut[n++] = ta;
	for (int k = 0; k < 3; k++) {
		real t = k == 0 ? tc.x : k == 1 ? tc.y : tc.z;
		if (t > ta && t < tb) {
			int i = n++;
			for (; i > 1 && cut[i - 1] > t; i--)
				cut[i] = cut[i - 1];
			cut[i] = t;
		}
	}
	cut[n++] = tb;
	for (int i = 0; i + 1 < n; i++) {
		real3 oct = sign(P + (real)0.5 * (cut[i] + cut[i + 1]) * D);
		real t = concave ? se_newton(P, D, pe, qe, cut[i], cut[i + 1], (real)-1, oct)
		                 : se_first_crossing(P, D, pe, qe, oct, cut[i], cut[i + 1]);
		if (t >= (real)0) {
			float ft = (float)t;
			return ft > tmin && ft < tmax ? ft : tmax;
		}
	}
	return tmax;
}

/* POV-Ray's normal (super.cpp), the function's gradient. */
static inline float3 superellipsoid_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float4 ex = intersect_data(prims, p);
	float pe = ex.x + ex.y, qe = ex.z + ex.w;
	float3 v = intersect_to_local(p, x), n = (float3)(0.0f);
	float ax = fabs(v.x), ay = fabs(v.y), r = 0.0f;
	float hi = fmax(ax, ay), g1 = hi > 0.0f ? hi * pow(1.0f + pow(fmin(ax, ay) / hi, pe), 1.0f / pe) : 0.0f;
	float g1q = pow(g1, qe);
	if (v.z != 0.0f)
		n.z = pow(fabs(v.z), qe) / v.z;
	if (ax > ay) {
		r = pow(ay / ax, pe);
		n.x = g1q / v.x;
		n.y = v.y != 0.0f ? g1q * r / v.y : 0.0f;
	} else if (v.y != 0.0f) {
		r = pow(ax / ay, pe);
		n.x = v.x != 0.0f ? g1q * r / v.x : 0.0f;
		n.y = g1q / v.y;
	}
	n.z *= 1.0f + r;
	return intersect_normal_to_world(p, n);
}

static inline bool superellipsoid_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float4 ex = intersect_data(prims, p);
	real3 v = intersect_to_local_real(p, x);
	return se_gauge(v, se_exponent(ex.x, ex.y), se_exponent(ex.z, ex.w)) - (real)1 < (real)1e-10;
}
