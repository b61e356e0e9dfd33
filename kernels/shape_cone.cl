/* shape_cone.cl: POV-Ray's cylinder and cone (src/shape_cone.c), each kept as
 * the map from world space to its own space, where
 *   cylinder: x^2 + y^2 = 1, 0 <= z <= 1;
 *   cone: x^2 + y^2 = r(z)^2, 0 <= z <= 1, with r(z) = dist + (1 - dist) z
 *   the radius, 1 at the larger end and dist at the other (dist < 0: two
 *   cones point to point). This is POV-Ray's cone space (x^2 + y^2 = z^2,
 *   dist <= z <= 1) stretched along z to the shape's length: a cone that is
 *   nearly a cylinder has its point far away, where POV-Ray's space would
 *   leave the intersection to cancellation in single precision.
 * Its PRIM_DATA records: x dist (0 for a cylinder), y 1 when its ends are
 * capped, z an emitting cylinder's probability of sampling its side; then the
 * centre (xyz), about which the rows map (cone_local).
 *
 * A capped one is intersected as a solid: the parts of the ray inside the
 * quadric, cut to the slab between the ends, so a ray through the rim meets the
 * side or the end and never slips between them. The ray starts from its point
 * nearest the axis (cone_start), which keeps the roots' precision when the
 * shape is far away (as for spheres) and where the ray grazes the side or
 * passes by a cone's point. */

/* A point in the shape's space. */
static inline float3 cone_local(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_to_local_about(p, prims[p->link + 1].a.xyz, x);
}

/* The t of the ray's point nearest the axis between the ends (x = y = 0,
 * 0 <= z <= 1): where the quadric's terms are smallest near where the ray
 * meets it, so they cancel least. */
static inline float cone_start(float3 oo, float3 dd)
{
	float a = dd.x * dd.x + dd.y * dd.y, dd2 = dot(dd, dd);
	if (a > 0.0f) {
		float t = -(oo.x * dd.x + oo.y * dd.y) / a, z = oo.z + t * dd.z;
		if (z >= 0.0f && z <= 1.0f)
			return t;
		return dot((float3)(0.0f, 0.0f, z < 0.0f ? 0.0f : 1.0f) - oo, dd) / dd2;
	}
	return (0.5f - oo.z) * dd.z / dd2;
}

/* The slab between the ends, z from z0 to z1, along the ray: [*lo, *hi];
 * false when the ray runs beside it. */
static inline bool cone_slab(float3 oo, float3 dd, float z0, float z1, float *lo, float *hi)
{
	if (dd.z == 0.0f) {
		*lo = -INFINITY;
		*hi = INFINITY;
		return oo.z >= z0 && oo.z <= z1;
	}
	float a = (z0 - oo.z) / dd.z, b = (z1 - oo.z) / dd.z;
	*lo = fmin(a, b);
	*hi = fmax(a, b);
	return true;
}

/* The roots lo <= hi of A t^2 + 2 B t + C = 0 (A != 0), given s =
 * sqrt(B^2 - A C) and K, the sum of the magnitudes of C's terms. The root
 * q / A has no cancellation; the other is C / q, or (-B + sign(B) s) / A,
 * whichever rounds less: C / q loses about K / |q| and the other |q| / |A|.
 * C / q alone fails a ray that grazes the surface near the point it starts
 * from, where q, B and s all vanish (Numerical Recipes' form assumes they do
 * not). */
static inline float2 cone_roots(float A, float B, float C, float s, float K)
{
	float q = B > 0.0f ? -B - s : -B + s;
	float u = q / A, v = q * q > K * fabs(A) ? C / q : (B > 0.0f ? -B + s : -B - s) / A;
	return (float2)(fmin(u, v), fmax(u, v));
}

/* The nearest of ts + c[0..3] in (tmin, tmax), else tmax; unused entries are INFINITY. */
static inline float cone_nearest(float ts, float4 c, float tmin, float tmax)
{
	float4 v = ts + c;
	v = select((float4)(INFINITY), v, v > tmin);
	float best = fmin(fmin(v.x, v.y), fmin(v.z, v.w));
	return best < tmax ? best : tmax;
}

static inline float cylinder_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                                float tmin, float tmax)
{
	float3 oo = cone_local(prims, p, o), dd = intersect_dir_to_local(p, d);
	bool capped = intersect_data(prims, p).y != 0.0f;
	float ts = cone_start(oo, dd);
	oo += ts * dd;
	/* inside the infinite cylinder: [s0, s1] */
	float a = dd.x * dd.x + dd.y * dd.y, b = oo.x * dd.x + oo.y * dd.y, s0 = -INFINITY, s1 = INFINITY;
	if (a > 0.0f) {
		float2 f = oo.xy - (b / a) * dd.xy;   /* the nearest point to the axis keeps precision */
		float disc = a * (1.0f - dot(f, f));
		if (disc < 0.0f)
			return tmax;
		float2 r = cone_roots(a, b, dot(oo.xy, oo.xy) - 1.0f, sqrt(disc), dot(oo.xy, oo.xy) + 1.0f);
		s0 = r.x;
		s1 = r.y;
	} else if (dot(oo.xy, oo.xy) > 1.0f) {
		return tmax;
	}
	float lo, hi;
	if (!cone_slab(oo, dd, 0.0f, 1.0f, &lo, &hi))
		return tmax;
	if (capped) {
		float enter = fmax(s0, lo), leave = fmin(s1, hi);
		if (!(enter <= leave))
			return tmax;
		return cone_nearest(ts, (float4)(enter, leave, INFINITY, INFINITY), tmin, tmax);
	}
	if (a == 0.0f)   /* along the axis: no side */
		return tmax;
	return cone_nearest(ts, (float4)(s0 >= lo && s0 <= hi ? s0 : INFINITY, s1 >= lo && s1 <= hi ? s1 : INFINITY,
	                                 INFINITY, INFINITY), tmin, tmax);
}

static inline float cone_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                            float tmin, float tmax)
{
	float3 oo = cone_local(prims, p, o), dd = intersect_dir_to_local(p, d);
	float4 data = intersect_data(prims, p);
	float k0 = data.x, k1 = 1.0f - data.x;   /* r(z) = k0 + k1 z */
	bool capped = data.y != 0.0f;
	float ts = cone_start(oo, dd);
	oo += ts * dd;
	/* x^2 + y^2 - r(z)^2 along the ray is A t^2 + 2 B t + C; inside the
	 * (double) cone where it is <= 0: [in.x, in.y] and [in.z, in.w] (empty:
	 * INFINITY), and the side's roots r0 <= r1 (INFINITY: none) */
	float ro = k0 + k1 * oo.z, rd = k1 * dd.z;
	float A = dd.x * dd.x + dd.y * dd.y - rd * rd;
	float B = oo.x * dd.x + oo.y * dd.y - ro * rd;
	float C = oo.x * oo.x + oo.y * oo.y - ro * ro;
	float4 in = (float4)(-INFINITY, INFINITY, INFINITY, INFINITY);
	float r0 = INFINITY, r1 = INFINITY;
	if (A == 0.0f) {
		if (B != 0.0f) {
			r0 = -0.5f * C / B;
			in.xy = B > 0.0f ? (float2)(-INFINITY, r0) : (float2)(r0, INFINITY);
		} else if (C > 0.0f) {
			return tmax;
		}
	} else {
		float disc = B * B - A * C;
		if (disc >= 0.0f) {
			float2 r = cone_roots(A, B, C, sqrt(disc), oo.x * oo.x + oo.y * oo.y + ro * ro);
			r0 = r.x;
			r1 = r.y;
			in = A > 0.0f ? (float4)(r0, r1, INFINITY, INFINITY) : (float4)(-INFINITY, r0, r1, INFINITY);
		} else if (A > 0.0f) {
			return tmax;
		}   /* else the whole line is inside */
	}
	float lo, hi;
	if (!cone_slab(oo, dd, 0.0f, 1.0f, &lo, &hi))
		return tmax;
	if (capped) {
		float e0 = fmax(in.x, lo), x0 = fmin(in.y, hi), e1 = fmax(in.z, lo), x1 = fmin(in.w, hi);
		bool first = e0 <= x0, second = in.z != INFINITY && e1 <= x1;
		return cone_nearest(ts, (float4)(first ? e0 : INFINITY, first ? x0 : INFINITY, second ? e1 : INFINITY,
		                                 second ? x1 : INFINITY), tmin, tmax);
	}
	return cone_nearest(ts, (float4)(r0 >= lo && r0 <= hi ? r0 : INFINITY, r1 >= lo && r1 <= hi ? r1 : INFINITY,
	                                 INFINITY, INFINITY), tmin, tmax);
}

/* The normal at q, a point of the shape in its space, where its radius is
 * k0 + k1 z: of the side, or of the end the point is on. Which one is the
 * surface nearest in world units, to first order (|f| / |grad f| for the side
 * f = 0, whose gradient goes to world space by the rows), so that a point near
 * the rim goes to the right part however the shape is stretched. */
static inline float3 cone_part_normal(global const dev_prim *p, float3 q, float k0, float k1, bool capped)
{
	float r = k0 + k1 * q.z;
	float3 side = (float3)(q.x, q.y, -k1 * r);   /* half the gradient of x^2 + y^2 - r^2 */
	if (!capped)
		return side;
	float f = q.x * q.x + q.y * q.y - r * r;
	float to_side = fabs(f) / (2.0f * length(side.x * p->a.xyz + side.y * p->b.xyz + side.z * p->c.xyz));
	float to_cap = fabs(q.z - 1.0f), to_base = fabs(q.z);
	if (fmin(to_cap, to_base) / length(p->c.xyz) < to_side)   /* to_side is infinite on the axis */
		return (float3)(0.0f, 0.0f, to_cap <= to_base ? 1.0f : -1.0f);
	return side;
}

static inline float3 cylinder_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = cone_local(prims, p, x);
	return intersect_normal_to_world(p, cone_part_normal(p, q, 1.0f, 0.0f, intersect_data(prims, p).y != 0.0f));
}

static inline float3 cone_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = cone_local(prims, p, x);
	float4 data = intersect_data(prims, p);
	return intersect_normal_to_world(p, cone_part_normal(p, q, data.x, 1.0f - data.x, data.y != 0.0f));
}

/* POV-Ray's Inside: the solid, open or not; the surface counts as inside an
 * open one (POV-Ray's EPSILON leans that way) and outside a closed one. */
static inline bool cone_inside_at(float3 q, float k0, float k1, bool capped)
{
	float w2 = q.x * q.x + q.y * q.y, r = k0 + k1 * q.z, r2 = r * r;
	if (capped)
		return w2 < r2 && q.z > 0.0f && q.z < 1.0f;
	return w2 <= r2 && q.z >= 0.0f && q.z <= 1.0f;
}

static inline bool cylinder_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return cone_inside_at(cone_local(prims, p, x), 1.0f, 0.0f, intersect_data(prims, p).y != 0.0f);
}

static inline bool cone_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float4 data = intersect_data(prims, p);
	return cone_inside_at(cone_local(prims, p, x), data.x, 1.0f - data.x, data.y != 0.0f);
}

/* A cylinder as an emitter (shape.cl's shape_emit_sample and
 * shape_emit_pdf). Its record's a.z is the probability of sampling the side
 * rather than an end (1 when open), which lowering sets to the side's share
 * of the area in world space (src/lower_emitter.c); the side is sampled
 * uniformly in its own space (angle and height), the ends as the disc is. In
 * world space the ends stay uniform under any transform, and the side too
 * under a similarity; a cylinder scaled across its axis (an elliptic one) has
 * the density over its side that cylinder_emit_pdf says, one over the area
 * scale at the point, so the estimate stays exact, only less even. */
static inline bool cylinder_emit_sample(global const dev_prim *prims, global const dev_prim *p, float3 x, float u1,
                                        float u2, float3 *wi, float3 *pos)
{
	float4 data = intersect_data(prims, p);
	float side = data.y != 0.0f ? data.z : 1.0f, phi = 2.0f * M_PI_F * u2;
	float3 q;
	if (u1 < side) {
		q = (float3)(cos(phi), sin(phi), u1 / side);
	} else {
		float u = (u1 - side) / (1.0f - side), end = u < 0.5f ? 0.0f : 1.0f;   /* each end, half the rest */
		float r = sqrt(2.0f * u - end);
		q = (float3)(r * cos(phi), r * sin(phi), end);
	}
	*pos = intersect_to_world_about(p, prims[p->link + 1].a.xyz, q);
	*wi = normalize(*pos - x);
	return true;
}

/* The density of the point t along wi from x in solid angle, pick times it:
 * the part's probability over its area in its own space (2 pi for the side, pi
 * an end) and over the area scale there. */
static inline float cylinder_emit_pdf(global const dev_prim *prims, global const dev_prim *p, float3 x, float3 wi,
                                      float t, float pick, float area)
{
	float4 data = intersect_data(prims, p);
	bool capped = data.y != 0.0f;
	float side = capped ? data.z : 1.0f;
	float3 q = cone_local(prims, p, x + t * wi), n = cone_part_normal(p, q, 1.0f, 0.0f, capped);
	float share;
	if (n.z != 0.0f && n.x == 0.0f && n.y == 0.0f) {   /* an end */
		share = 0.5f * (1.0f - side) / M_PI_F;
	} else {
		float w = length(q.xy);
		if (!(w > 0.0f))   /* on the axis: no side there */
			return 0.0f;
		n = (float3)(q.x / w, q.y / w, 0.0f);
		share = side / (2.0f * M_PI_F);
	}
	return intersect_area_to_solid_angle(pick * share / intersect_area_scale(p, n), intersect_normal_to_world(p, n),
	                                     wi, t);
}
