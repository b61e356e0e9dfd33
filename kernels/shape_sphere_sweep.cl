/* shape_sphere_sweep.cl: POV-Ray's sphere_sweep, kept as the map from world
 * space to its own (about the centre of its box); its records
 * (src/shape_sphere_sweep.c, kernels/shared.h): a head (segments, tolerance,
 * the surface's depth), then per segment its box and the coefficients of u^0
 * to u^3 of its centre (xyz) and radius (w).
 *
 * A long sweep is several primitives, each holding a few segments (a chunk
 * record: its first segment, how many, and how far back the head is), whose
 * hits are checked against every segment.
 *
 * As src/shape_sphere_sweep.c, in double where the device has it: the spheres
 * where the ray touches a segment's envelope (the roots in [0, 1] of a
 * polynomial of degree 10 in u, kernels/roots.cl) and those at the segments'
 * ends give the points; the nearest not deeper than the head's depth inside
 * any segment is the hit. The normal and the inside test come from the least
 * power distance |x - C(u)|^2 - r(u)^2 over the segments. */

#define SWEEP_RECORDS 6   /* a segment's: box corners, four coefficients */

typedef struct {
	real3 c[4];
	real r[4];
	real3 lo, hi;
} sweep_seg;

/* The head record of p's sweep. */
static inline int sweep_head(global const dev_prim *prims, global const dev_prim *p)
{
	return p->link - (int)prims[p->link].a.z;
}

static inline sweep_seg sweep_segment_at(global const dev_prim *prims, int head, int j)
{
	int rec = head + 1 + SWEEP_RECORDS * j;
	sweep_seg g;
	g.lo = convert_real3(prims[rec].a.xyz);
	g.hi = convert_real3(prims[rec + 1].a.xyz);
	for (int k = 0; k < 4; k++) {
		float4 a = prims[rec + 2 + k].a;
		g.c[k] = convert_real3(a.xyz);
		g.r[k] = (real)a.w;
	}
	return g;
}

static inline real3 sweep_centre(const sweep_seg *g, real u)
{
	return ((g->c[3] * u + g->c[2]) * u + g->c[1]) * u + g->c[0];
}

static inline real sweep_radius(const sweep_seg *g, real u)
{
	return ((g->r[3] * u + g->r[2]) * u + g->r[1]) * u + g->r[0];
}

static inline bool sweep_in_box(const sweep_seg *g, real3 x, real slack)
{
	return !(x.x < g->lo.x - slack || x.x > g->hi.x + slack || x.y < g->lo.y - slack || x.y > g->hi.y + slack ||
	         x.z < g->lo.z - slack || x.z > g->hi.z + slack);
}

/* The least power distance from x over u in [0, 1], its u into *best_u. */
static inline real sweep_least_power(const sweep_seg *g, real3 x, real *best_u)
{
	real3 w[4] = { x - g->c[0], -g->c[1], -g->c[2], -g->c[3] };
	real f[7] = { 0, 0, 0, 0, 0, 0, 0 }, df[6], u[6];
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			f[i + j] += dot(w[i], w[j]) - g->r[i] * g->r[j];
	for (int k = 0; k < 6; k++)
		df[k] = (real)(k + 1) * f[k + 1];
	int n = roots_find(df, 5, (real)0, (real)1, u, 6);
	real best = INFINITY;
	for (int i = -1; i <= n; i++) {
		real v = i < 0 ? (real)0 : i == n ? (real)1 : u[i];
		real3 dd = x - sweep_centre(g, v);
		real rr = sweep_radius(g, v), pw = dot(dd, dd) - rr * rr;
		if (pw < best) {
			best = pw;
			*best_u = v;
		}
	}
	return best;
}

/* The least power distance over the segments (those whose box, grown by
 * slack, holds x, when near), with the centre of its sphere into *centre. */
static inline real sweep_least(global const dev_prim *prims, int head, real3 x, bool near, real slack, real3 *centre)
{
	int n = (int)prims[head].a.x;
	real best = INFINITY;
	*centre = x - (real3)(0, 1, 0);
	for (int j = 0; j < n; j++) {
		sweep_seg g = sweep_segment_at(prims, head, j);
		if (near && !sweep_in_box(&g, x, slack))
			continue;
		real u, pw = sweep_least_power(&g, x, &u);
		if (pw < best) {
			best = pw;
			*centre = sweep_centre(&g, u);
		}
	}
	return best;
}

/* Whether x is deeper than eps inside a segment: no point of the surface. */
static inline bool sweep_deep_inside(global const dev_prim *prims, int head, real3 x, real eps)
{
	int n = (int)prims[head].a.x;
	for (int j = 0; j < n; j++) {
		sweep_seg g = sweep_segment_at(prims, head, j);
		if (!sweep_in_box(&g, x, (real)0))
			continue;
		real u, pw = sweep_least_power(&g, x, &u);
		if (!(pw < (real)0))
			continue;
		real r = fabs(sweep_radius(&g, u));
		if (r - sqrt(fmax(r * r + pw, (real)0)) > eps)
			return true;
	}
	return false;
}

/* The u in [0, 1] where the ray touches segment g's envelope (as
 * envelope_roots in src/shape_sphere_sweep.c). */
static inline int sweep_envelope_roots(const sweep_seg *g, real3 o, real3 d, real *u)
{
	real3 w[4] = { o - g->c[0], -g->c[1], -g->c[2], -g->c[3] };
	real3 dc[3];
	real dr[3], P[6] = { 0, 0, 0, 0, 0, 0 }, Q[3], B[4], E[7] = { 0, 0, 0, 0, 0, 0, 0 }, F[11];
	for (int k = 0; k < 11; k++)
		F[k] = 0;
	for (int k = 0; k < 3; k++) {
		dc[k] = (real)(k + 1) * g->c[k + 1];
		dr[k] = (real)(k + 1) * g->r[k + 1];
		Q[k] = dot(d, dc[k]);
	}
	for (int i = 0; i < 4; i++) {
		B[i] = dot(d, w[i]);
		for (int j = 0; j < 4; j++)
			E[i + j] += dot(w[i], w[j]) - g->r[i] * g->r[j];
		for (int j = 0; j < 3; j++)
			P[i + j] += dot(w[i], dc[j]) + g->r[i] * dr[j];
	}
	real A = dot(d, d);
	for (int i = 0; i < 6; i++)
		for (int j = 0; j < 6; j++) {
			F[i + j] += A * P[i] * P[j];
			if (j < 3)
				for (int k = 0; k < 4; k++)
					F[i + j + k] -= (real)2 * P[i] * Q[j] * B[k];
		}
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 7; k++)
				F[i + j + k] += Q[i] * Q[j] * E[k];
	return roots_find(F, 10, (real)-1e-12, (real)1, u, 10);
}

static inline float sphere_sweep_intersect(float3 wo, float3 wd, global const dev_prim *prims, global const dev_prim *p,
                                    float tmin, float tmax)
{
	float4 chunk = prims[p->link].a;
	int head = sweep_head(prims, p), first = (int)chunk.x, end = first + (int)chunk.y;
	float4 h = prims[head].a;
	real3 o = intersect_to_local_real(p, wo), d = intersect_dir_to_local_real(p, wd);
	real len = length(d), eps = (real)h.z;
	if (!(len > (real)0))
		return tmax;
	/* POV-Ray's tolerance: no hit nearer than it */
	real lo = fmax((real)tmin, (real)h.y / len), best = (real)tmax;
	for (int j = first; j < end; j++) {
		sweep_seg g = sweep_segment_at(prims, head, j);
		real t0 = lo, t1 = best;
		for (int q = 0; q < 3 && t0 <= t1; q++) {
			real oq = q == 0 ? o.x : q == 1 ? o.y : o.z, dq = q == 0 ? d.x : q == 1 ? d.y : d.z;
			real bl = q == 0 ? g.lo.x : q == 1 ? g.lo.y : g.lo.z, bh = q == 0 ? g.hi.x : q == 1 ? g.hi.y : g.hi.z;
			if (dq == (real)0) {
				if (oq < bl || oq > bh)
					t0 = INFINITY;
				continue;
			}
			real a = (bl - oq) / dq, b = (bh - oq) / dq;
			t0 = fmax(t0, fmin(a, b));
			t1 = fmin(t1, fmax(a, b));
		}
		if (!(t0 <= t1))
			continue;
		real u[12];
		int m = sweep_envelope_roots(&g, o, d, u);
		u[m++] = 0;
		u[m++] = 1;
		for (int i = 0; i < m; i++) {
			real3 w = o - sweep_centre(&g, u[i]);
			real rr = sweep_radius(&g, u[i]);
			real A = dot(d, d), B = dot(w, d), C = dot(w, w) - rr * rr, disc = B * B - A * C;
			if (!(disc > (real)0))
				continue;
			real q = sqrt(disc);
			for (int h = 0; h < 2; h++) {
				real t = h == 0 ? (-B - q) / A : (-B + q) / A;
				/* the first whose float is past tmin (a CSG's last stop) */
				if (!(t > lo && t < best) || !((float)t > tmin))
					continue;
				if (!sweep_deep_inside(prims, head, o + t * d, eps))
					best = t;
			}
		}
	}
	return best < (real)tmax ? (float)best : tmax;
}

static inline float3 sphere_sweep_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	/* a point of the surface is in its segment's box, give or take rounding */
	int head = sweep_head(prims, p);
	real3 v = intersect_to_local_real(p, x), c;
	if (sweep_least(prims, head, v, true, (real)1000 * (real)prims[head].a.z, &c) == INFINITY)
		sweep_least(prims, head, v, false, (real)0, &c);
	float3 n = convert_float3(v - c);
	if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)
		n.y = 1.0f;
	return intersect_normal_to_world(p, n);
}

static inline bool sphere_sweep_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	real3 c;
	return sweep_least(prims, sweep_head(prims, p), intersect_to_local_real(p, x), true, (real)0, &c) < (real)0;
}
