/* shape_blob.cl: POV-Ray's blob, kept as the map from world space to its own;
 * its records (src/shape_blob.c): the first's a.x its number of components
 * and a.y its threshold, then two a component: a.xyz one end (the centre) and
 * a.w the radius, b.xyz the other end (the same for a sphere) and b.w the
 * strength, c.x 1 when the component has a space of its own (a non-uniform
 * scale: POV-Ray's ellipsoidal components), whose map from the blob's space
 * is the next record's rows a, b, c.
 *
 * As trace() in src/shape_blob.c, in double where the device has it: the ray
 * is walked from stretch boundary to stretch boundary of the components'
 * pieces (a sphere, or a cylinder's cap, body and cap), and over each
 * stretch the pieces' quartics are added up and the first root of the sum
 * less the threshold taken (kernels/roots.cl). A component in a space of its
 * own sees the ray there, with the same t. */

typedef struct {
	real t0, t1, A, B, C, r2, s;
} blob_piece;

/* v (a point when w is 1, a direction when 0) in the space of the component
 * whose records start at rec. */
static inline real3 blob_own(global const dev_prim *prims, int rec, real3 v, real w)
{
	if (prims[rec].c.x == 0.0f)
		return v;
	global const dev_prim *m = &prims[rec + 1];
	return (real3)(dot(convert_real3(m->a.xyz), v) + w * (real)m->a.w, dot(convert_real3(m->b.xyz), v) + w * (real)m->b.w,
	               dot(convert_real3(m->c.xyz), v) + w * (real)m->c.w);
}

static inline bool blob_piece_of(global const dev_prim *prims, int rec, int k, real3 ro, real3 rd, blob_piece *out)
{
	float4 ea = prims[rec].a, eb = prims[rec].b;
	real3 o = blob_own(prims, rec, ro, (real)1), d = blob_own(prims, rec, rd, (real)0);
	real3 a = convert_real3(ea.xyz), b = convert_real3(eb.xyz), ax = b - a;
	real len = length(ax), r = (real)ea.w;
	bool sphere = !(len > (real)0);
	if (sphere && k > 0)
		return false;
	real3 w = o - (k == 2 ? b : a), dd = d;
	real s0 = 0, ds = 0;
	if (!sphere) {
		ax /= len;
		s0 = dot(o - a, ax);
		ds = dot(d, ax);
		if (k == 1) {
			w -= dot(w, ax) * ax;
			dd -= ds * ax;
		}
	}
	real A = dot(dd, dd), B = (real)2 * dot(dd, w), C = dot(w, w), r2 = r * r;
	real t0 = -INFINITY, t1 = INFINITY;
	if (A > (real)0) {
		real disc = B * B - (real)4 * A * (C - r2);
		if (!(disc > (real)0))
			return false;
		real q = sqrt(disc);
		t0 = (-B - q) / ((real)2 * A);
		t1 = (-B + q) / ((real)2 * A);
	} else if (!(C < r2)) {
		return false;
	}
	if (!sphere) {
		real lo = k == 0 ? -INFINITY : k == 1 ? (real)0 : len, hi = k == 0 ? (real)0 : k == 1 ? len : INFINITY;
		if (ds != (real)0) {
			real ta = (lo - s0) / ds, tb = (hi - s0) / ds;
			t0 = fmax(t0, fmin(ta, tb));
			t1 = fmin(t1, fmax(ta, tb));
		} else if (!(s0 >= lo && s0 <= hi)) {
			return false;
		}
	}
	if (!(t0 < t1))
		return false;
	blob_piece pc = { t0, t1, A, B, C, r2, (real)eb.w };
	*out = pc;
	return true;
}

static inline float blob_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p, float tmin,
                            float tmax)
{
	float4 head = prims[p->link].a;
	int n = (int)head.x;
	real threshold = (real)head.y;
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	real cur = -INFINITY;
	blob_piece pc;
	for (;;) {
		real next = INFINITY;
		for (int j = 0; j < n; j++)
			for (int k = 0; k < 3; k++)
				if (blob_piece_of(prims, p->link + 1 + 2 * j, k, P, D, &pc)) {
					if (pc.t0 > cur && pc.t0 < next)
						next = pc.t0;
					if (pc.t1 > cur && pc.t1 < next)
						next = pc.t1;
				}
		if (next == INFINITY || cur >= (real)tmax)
			return tmax;
		if (cur > -INFINITY && next > (real)tmin) {
			real mid = (real)0.5 * (cur + next), c[5] = { -threshold, 0, 0, 0, 0 };
			bool any = false;
			for (int j = 0; j < n; j++)
				for (int k = 0; k < 3; k++)
					if (blob_piece_of(prims, p->link + 1 + 2 * j, k, P, D, &pc) && pc.t0 < mid && mid < pc.t1) {
						real s = pc.s, r2 = pc.r2, r4 = r2 * r2;
						c[0] += s * ((real)1 - (real)2 * pc.C / r2 + pc.C * pc.C / r4);
						c[1] += s * ((real)-2 * pc.B / r2 + (real)2 * pc.B * pc.C / r4);
						c[2] += s * ((real)-2 * pc.A / r2 + (pc.B * pc.B + (real)2 * pc.A * pc.C) / r4);
						c[3] += s * (real)2 * pc.A * pc.B / r4;
						c[4] += s * pc.A * pc.A / r4;
						any = true;
					}
			real lo = fmax(cur, (real)tmin), hi = fmin(next, (real)tmax), u;
			/* the first root whose float is past tmin (a CSG's last stop) */
			for (int i = 0; any && i < 4 && roots_find(c, 4, lo, hi, &u, 1) == 1; i++) {
				float t = (float)u;
				if (t > tmin)
					return t < tmax ? t : tmax;
				lo = u;
			}
		}
		cur = next;
	}
}

/* The field at v (the blob's space) of the component whose records start at
 * rec, its gradient added to *g. */
static inline real blob_component_field(global const dev_prim *prims, int rec, real3 v, real3 *g)
{
	float4 ea = prims[rec].a, eb = prims[rec].b;
	real3 a = convert_real3(ea.xyz), ax = convert_real3(eb.xyz) - a, w = blob_own(prims, rec, v, (real)1) - a;
	real len2 = dot(ax, ax);
	if (len2 > (real)0)
		w -= clamp(dot(w, ax) / len2, (real)0, (real)1) * ax;
	real r2 = (real)ea.w * (real)ea.w, d2 = dot(w, w);
	if (d2 >= r2)
		return (real)0;
	real u = (real)1 - d2 / r2, s = (real)eb.w;
	real3 gl = s * (real)2 * u * ((real)-2 * w / r2);
	if (prims[rec].c.x != 0.0f) {   /* back to the blob's space: the transpose of the rows */
		global const dev_prim *m = &prims[rec + 1];
		gl = gl.x * convert_real3(m->a.xyz) + gl.y * convert_real3(m->b.xyz) + gl.z * convert_real3(m->c.xyz);
	}
	*g += gl;
	return s * u * u;
}

/* The field at v (the blob's space) and its gradient into *g. */
static inline real blob_field(global const dev_prim *prims, global const dev_prim *p, real3 v, real3 *g)
{
	int n = (int)prims[p->link].a.x;
	real f = 0;
	*g = (real3)(0);
	for (int j = 0; j < n; j++)
		f += blob_component_field(prims, p->link + 1 + 2 * j, v, g);
	return f;
}

static inline float3 blob_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	real3 g;
	blob_field(prims, p, intersect_to_local_real(p, x), &g);
	float3 n = convert_float3(-g);
	if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)
		n.y = 1.0f;
	return intersect_normal_to_world(p, n);
}

static inline bool blob_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	real3 g;
	return blob_field(prims, p, intersect_to_local_real(p, x), &g) > (real)prims[p->link].a.y;
}
