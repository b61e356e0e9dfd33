/* shape_julia_fractal.cl: POV-Ray's julia_fractal (src/shape_julia_fractal.c,
 * whose trace() this follows step for step in real): the ray marches from the
 * bounding sphere by the orbit's distance estimate (quaternions) or the
 * normal's step (hypercomplex numbers), at least 1/precision, until the set's
 * inside changes, and bisects the last step to 1e-7. Its four PRIM_DATA
 * records: shared.h. */

#define JULIA_TOLERANCE 1e-7

typedef struct {
	real c[4], slice[4], slice_dist, precision, exit, radius;
	int iterations, hyper, cube;
} julia_params;

static inline julia_params julia_params_of(global const dev_prim *prims, global const dev_prim *p)
{
	float4 c = prims[p->link].a, s = prims[p->link + 1].a, m = prims[p->link + 2].a, k = prims[p->link + 3].a;
	julia_params j;
	j.c[0] = c.x, j.c[1] = c.y, j.c[2] = c.z, j.c[3] = c.w;
	j.slice[0] = s.x, j.slice[1] = s.y, j.slice[2] = s.z, j.slice[3] = s.w;
	j.slice_dist = m.x, j.precision = m.y, j.exit = m.z, j.radius = m.w;
	j.iterations = (int)k.x;
	j.hyper = (int)k.y == JULIA_HYPERCOMPLEX;
	j.cube = (int)k.z == JULIA_CUBE;
	return j;
}

typedef struct {
	real x, y, z, w;
} julia_q;

static inline julia_q julia_qmul(julia_q a, julia_q b)
{
	julia_q r;
	r.x = a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w;
	r.y = a.x * b.y + a.y * b.x + a.w * b.z - a.z * b.w;
	r.z = a.x * b.z + a.z * b.x + a.y * b.w - a.w * b.y;
	r.w = a.x * b.w + a.w * b.x + a.z * b.y - a.y * b.z;
	return r;
}

/* POV-Ray's HMult(r, a, b). */
static inline julia_q julia_hmul(julia_q a, julia_q b)
{
	julia_q r;
	r.x = a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w;
	r.y = a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w;
	r.z = a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w;
	r.w = a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w;
	return r;
}

static inline real3 julia_hnormal(julia_q h, julia_q n)
{
	return (real3)(h.x * n.x + h.y * n.y + h.z * n.z + h.w * n.w, -h.y * n.x + h.x * n.y - h.w * n.z + h.z * n.w,
	               -h.z * n.x - h.w * n.y + h.x * n.z + h.y * n.w);
}

/* One row of the quaternion normal, one step of the orbit at z. */
static inline julia_q julia_qderiv(julia_q m, julia_q z, int cube)
{
	real d = z.y * z.y + z.z * z.z + z.w * z.w, x2 = z.x * z.x;
	julia_q r;
	if (cube) {
		real x3 = x2 - d, x4 = 3 * x2 - d;
		real dt = 2 * (m.y * z.y + m.z * z.z + m.w * z.w), dt2 = 6 * z.x * m.x - dt;
		r.x = (m.x * x3 - z.x * dt) * 3;
		r.y = m.y * x4 + z.y * dt2;
		r.z = m.z * x4 + z.z * dt2;
		r.w = m.w * x4 + z.w * dt2;
	} else {
		r.x = m.x * z.x - m.y * z.y - m.z * z.z - m.w * z.w;
		r.y = m.x * z.y + z.x * m.y;
		r.z = m.x * z.z + z.x * m.z;
		r.w = m.x * z.w + z.x * m.w;
	}
	return r;
}

static inline julia_q julia_step(const julia_params *j, julia_q z)
{
	julia_q r;
	if (j->hyper) {
		real yz = z.y * z.y + z.z * z.z, xw = z.x * z.x + z.w * z.w;
		r.x = xw - yz + j->c[0];
		r.y = 2 * (z.x * z.y - z.z * z.w) + j->c[1];
		r.z = 2 * (z.x * z.z - z.w * z.y) + j->c[2];
		r.w = 2 * (z.x * z.w + z.y * z.z) + j->c[3];
	} else if (j->cube) {
		real d = z.y * z.y + z.z * z.z + z.w * z.w, x2 = z.x * z.x, t = 3 * x2 - d;
		r.x = z.x * (x2 - 3 * d) + j->c[0];
		r.y = z.y * t + j->c[1];
		r.z = z.z * t + j->c[2];
		r.w = z.w * t + j->c[3];
	} else {
		real d = z.y * z.y + z.z * z.z + z.w * z.w;
		r.y = 2 * z.x * z.y + j->c[1];
		r.z = 2 * z.x * z.z + j->c[2];
		r.w = 2 * z.x * z.w + j->c[3];
		r.x = z.x * z.x - d + j->c[0];
	}
	return r;
}

/* The orbit of p: whether it stays; *dist the marching's step (when want_dist);
 * *normal, for a point that stays (or, for want_dist == 2, the normal from
 * wherever the orbit leaves: a hit rounded just outside still gets one). */
static inline int julia_orbit(const julia_params *j, real3 p, real3 dir, int want_dist, real *dist, real3 *normal)
{
	julia_q z;
	z.x = p.x, z.y = p.y, z.z = p.z;
	z.w = (j->slice_dist - j->slice[0] * p.x - j->slice[1] * p.y - j->slice[2] * p.z) / j->slice[3];
	julia_q prod = z, n1 = { 1, 0, 0, 0 }, n2 = { 0, 1, 0, 0 }, n3 = { 0, 0, 1, 0 };
	real pw = j->hyper ? (real)2 : j->cube ? (real)1 / 3 : (real)0.5;
	*dist = j->precision;
	for (int i = 1; i <= j->iterations; i++) {
		real norm = z.x * z.x + z.y * z.y + z.z * z.z + z.w * z.w;
		if (norm > j->exit) {
			if (want_dist == 1 && !j->hyper) {
				real p2 = prod.x * prod.x + prod.y * prod.y + prod.z * prod.z + prod.w * prod.w;
				*dist = pw * sqrt(norm / p2) * log(norm);
			} else if (want_dist == 1) {
				real s = j->cube ? (real)1 : pw;
				julia_q n = { z.x * s, z.y * s, z.z * s, z.w * s };
				real st = dot(julia_hnormal(prod, n), dir);
				if (st < -JULIA_TOLERANCE) {
					st = -2 * st;
					if (norm > j->precision * st && norm < 30 * j->precision * st)
						*dist = norm / st;
				}
			}
			if (want_dist != 2)
				return 0;
			break;
		}
		if (!j->hyper) {
			n1 = julia_qderiv(n1, z, j->cube);
			n2 = julia_qderiv(n2, z, j->cube);
			n3 = julia_qderiv(n3, z, j->cube);
		} else if (i >= 2) {
			prod = julia_hmul(z, prod);
			pw *= 2;
		}
		z = julia_step(j, z);
		if (!j->hyper) {
			prod = julia_qmul(prod, z);
			pw /= j->cube ? 3 : 2;
		}
	}
	if (want_dist == 2) {
		if (j->hyper) {
			real s = j->cube ? (real)1 : pw;
			julia_q n = { z.x * s, z.y * s, z.z * s, z.w * s };
			*normal = julia_hnormal(prod, n);
		} else {
			*normal = (real3)(n1.x * z.x + n1.y * z.y + n1.z * z.z + n1.w * z.w,
			                  n2.x * z.x + n2.y * z.y + n2.z * z.z + n2.w * z.w,
			                  n3.x * z.x + n3.y * z.y + n3.z * z.z + n3.w * z.w);
		}
	}
	return 1;
}

static inline float julia_fractal_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                     float tmin, float tmax)
{
	julia_params j = julia_params_of(prims, p);
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	real len = length(D);
	if (!(len > 0))
		return tmax;
	D /= len;
	real b = dot(P, D), c = dot(P, P) - j.radius * j.radius, disc = b * b - c;
	if (disc < 0)
		return tmax;
	real depth = -b - sqrt(disc), depth_max = fmin(-b + sqrt(disc), (real)tmax * len);
	depth = fmax(depth, fmax((real)JULIA_TOLERANCE, (real)tmin * len));
	if (depth_max < JULIA_TOLERANCE || depth >= depth_max)
		return tmax;
	real dist, dnext;
	real3 nrm, next = P + depth * D, ip;
	int current = julia_orbit(&j, next, D, 1, &dist, &nrm);
	if (current) {   /* starting inside */
		depth += 2 * JULIA_TOLERANCE;
		if (depth > depth_max)
			return tmax;
		next = P + depth * D;
		current = julia_orbit(&j, next, D, 1, &dist, &nrm);
	}
	for (;;) {
		if (dist < j.precision)
			dist = j.precision;
		depth += dist;
		if (depth > depth_max)
			return tmax;
		ip = next;
		next = P + depth * D;
		if (julia_orbit(&j, next, D, 1, &dnext, &nrm) != current) {
			depth -= dist;
			break;
		}
		dist = dnext;
	}
	while (dist > JULIA_TOLERANCE) {   /* bisection */
		dist *= (real)0.5;
		real3 mid = ip + dist * D;
		if (julia_orbit(&j, mid, D, 0, &dnext, &nrm) == current) {
			ip = mid;
			depth += dist;
			if (depth > depth_max)
				return tmax;
		}
	}
	if (!current)
		depth += dist;
	float t = (float)(depth / len);
	return t > tmin && t < tmax ? t : tmax;
}

/* POV-Ray's Normal_Calc at the hit, which the marching left just inside: a
 * hit that rounding put outside (its orbit escapes early, and the normal of
 * that shorter orbit is another) moves in against the shorter orbit's normal,
 * by steps that double from 1e-7, until its orbit stays. */
static inline float3 julia_fractal_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	julia_params j = julia_params_of(prims, p);
	real dist;
	real3 q = intersect_to_local_real(p, x), n = (real3)((real)0, (real)0, (real)1);
	if (!julia_orbit(&j, q, n, 0, &dist, &n)) {
		julia_orbit(&j, q, n, 2, &dist, &n);
		real len = length(n);
		if (len > 0) {
			real3 in = -n / len;
			for (real s = (real)JULIA_TOLERANCE; s < (real)1e-3; s *= 2)
				if (julia_orbit(&j, q + s * in, n, 0, &dist, &n)) {
					q += s * in;
					break;
				}
		}
	}
	julia_orbit(&j, q, n, 2, &dist, &n);
	return intersect_normal_to_world(p, convert_float3(n));
}

static inline bool julia_fractal_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	julia_params j = julia_params_of(prims, p);
	real dist;
	real3 n;
	return julia_orbit(&j, intersect_to_local_real(p, x), n, 0, &dist, &n) != 0;
}
