/* shape_prism.cl: POV-Ray's prism, and polygon and text drawn as one
 * (src/prism.h says how they are kept): edges in the xz plane of the prism's
 * own space, swept along y from h1 to h2, straight or toward the apex
 * (conic_sweep); the caps are the points of the plane inside the outline by
 * the even-odd rule, a text's glyphs each on its own, united. The edges come
 * in chunks of a few, each with its box, so a ray skips the chunks it passes
 * by. Every edge is turned so that the inside is on its left. */

/* The record i of a prism's records. */
static inline float4 prism_rec(global const dev_prim *prims, global const dev_prim *p, int i)
{
	return prims[p->link + i].a;
}

/* Whether the point (x, z) of the plane is inside the outline. */
static inline bool prism_in_outline(global const dev_prim *prims, global const dev_prim *p, float x, float z)
{
	int chunks = as_int(prism_rec(prims, p, 0).z), r = 2;
	bool in = false, odd = false;
	for (int c = 0; c < chunks; c++) {
		float4 box = prism_rec(prims, p, r), info = prism_rec(prims, p, r + 1);
		int n = as_int(info.x);
		if (as_int(info.y)) {   /* a new glyph */
			in = in || odd;
			odd = false;
		}
		if (z >= box.y && z <= box.w && x <= box.z)
			for (int i = 0; i < n; i++) {
				float4 e = prism_rec(prims, p, r + 2 + i);
				if ((e.y > z) != (e.w > z) && x < e.x + (z - e.y) * (e.z - e.x) / (e.w - e.y))
					odd = !odd;
			}
		r += 2 + n;
	}
	return in || odd;
}

/* The parameters (enter, leave) of the ray in the box lo..hi, enter > leave when it misses. */
static inline float2 prism_slab(float3 o, float3 inv, float3 lo, float3 hi)
{
	float3 t0 = (lo - o) * inv, t1 = (hi - o) * inv;
	float3 a = fmin(t0, t1), b = fmax(t0, t1);
	return (float2)(fmax(fmax(a.x, a.y), a.z), fmin(fmin(b.x, b.y), b.z));
}

/* The box of a chunk's part of the solid, from its box in the plane. */
static inline void prism_chunk_box(float4 box, float h1, float h2, bool conic, float3 *lo, float3 *hi)
{
	if (conic) {
		float4 a = box * h1, b = box * h2;
		float4 l = fmin(a, b), h = fmax(a, b);
		*lo = (float3)(fmin(l.x, l.z), h1, fmin(l.y, l.w));
		*hi = (float3)(fmax(h.x, h.z), h2, fmax(h.y, h.w));
	} else {
		*lo = (float3)(box.x, h1, box.y);
		*hi = (float3)(box.z, h2, box.w);
	}
}

#define PRISM_EDGE_EPS 1e-6f   /* how far past its ends an edge is still hit: no cracks at corners */

static inline float prism_intersect(float3 wo, float3 wd, global const dev_prim *prims, global const dev_prim *p,
                             float tmin, float tmax)
{
	float3 o = intersect_to_local(p, wo), d = intersect_dir_to_local(p, wd), inv = 1.0f / d;
	float4 head = prism_rec(prims, p, 0);
	float h1 = head.x, h2 = head.y;
	int chunks = as_int(head.z), flags = as_int(head.w);
	bool conic = (flags & PRISM_CONIC) != 0;
	float3 lo, hi;
	prism_chunk_box(prism_rec(prims, p, 1), h1, h2, conic, &lo, &hi);
	float2 span = prism_slab(o, inv, lo, hi);
	if (!(span.x <= span.y) || span.y <= tmin || span.x >= tmax)
		if (!(flags & PRISM_FLAT))   /* a flat box's slab may be 0 * inf */
			return tmax;
	float best = tmax;
	int caps = (flags & PRISM_FLAT) ? 1 : (flags & PRISM_OPEN) ? 0 : 2;
	for (int c = 0; c < caps; c++) {
		float hc = c ? h2 : h1, t = (hc - o.y) / d.y;
		if (!(t > tmin && t < best))
			continue;
		float x = o.x + t * d.x, z = o.z + t * d.z;
		if (conic) {
			if (hc == 0.0f)
				continue;
			x /= hc;
			z /= hc;
		}
		if (prism_in_outline(prims, p, x, z))
			best = t;
	}
	if (flags & PRISM_FLAT)
		return best;
	int r = 2;
	for (int c = 0; c < chunks; c++) {
		float4 box = prism_rec(prims, p, r);
		int n = as_int(prism_rec(prims, p, r + 1).x);
		prism_chunk_box(box, h1, h2, conic, &lo, &hi);
		float2 s = prism_slab(o, inv, lo, hi);
		if (s.x <= s.y && s.y > tmin && s.x < best)
			for (int i = 0; i < n; i++) {
				float4 e = prism_rec(prims, p, r + 2 + i);
				float ex = e.z - e.x, ez = e.w - e.y, t, u;
				if (conic) {
					float3 out = (float3)(ez, -(ez * e.x - ex * e.y), -ex);
					float den = dot(out, d);
					if (den == 0.0f)
						continue;
					t = -dot(out, o) / den;
					float y = o.y + t * d.y;
					if (y == 0.0f)
						continue;
					float px = (o.x + t * d.x) / y - e.x, pz = (o.z + t * d.z) / y - e.y;
					u = (px * ex + pz * ez) / (ex * ex + ez * ez);
				} else {
					float den = d.x * ez - d.z * ex;
					if (den == 0.0f)
						continue;
					float wx = e.x - o.x, wz = e.y - o.z;
					t = (wx * ez - wz * ex) / den;
					u = (wx * d.z - wz * d.x) / den;
				}
				float y = o.y + t * d.y;
				if (t > tmin && t < best && u >= -PRISM_EDGE_EPS && u <= 1.0f + PRISM_EDGE_EPS && y >= h1 && y <= h2)
					best = t;
			}
		r += 2 + n;
	}
	return best;
}

/* The cap or side the point is nearest to. */
static inline float3 prism_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float4 head = prism_rec(prims, p, 0);
	float h1 = head.x, h2 = head.y;
	int chunks = as_int(head.z), flags = as_int(head.w);
	bool conic = (flags & PRISM_CONIC) != 0;
	if (flags & PRISM_FLAT)
		return intersect_normal_to_world(p, (float3)(0.0f, 1.0f, 0.0f));
	float3 n = (float3)(0.0f, -1.0f, 0.0f);
	float best = INFINITY;
	if (!(flags & PRISM_OPEN)) {
		best = fabs(q.y - h1);
		if (fabs(q.y - h2) < best) {
			best = fabs(q.y - h2);
			n = (float3)(0.0f, 1.0f, 0.0f);
		}
	}
	/* conic: the edges at the point's height */
	float k = conic ? q.y : 1.0f;
	int r = 2;
	for (int c = 0; c < chunks; c++) {
		float4 box = prism_rec(prims, p, r) * k;
		int n_e = as_int(prism_rec(prims, p, r + 1).x);
		float bx = fmax(fmax(fmin(box.x, box.z) - q.x, q.x - fmax(box.x, box.z)), 0.0f);
		float bz = fmax(fmax(fmin(box.y, box.w) - q.z, q.z - fmax(box.y, box.w)), 0.0f);
		if (bx * bx + bz * bz < best * best)
			for (int i = 0; i < n_e; i++) {
				float4 e = prism_rec(prims, p, r + 2 + i) * k;
				float2 a = (float2)(e.x, e.y), ed = (float2)(e.z, e.w) - a, w = (float2)(q.x, q.z) - a;
				float s = clamp(dot(w, ed) / dot(ed, ed), 0.0f, 1.0f);
				float dist = length(w - s * ed);
				if (dist < best) {
					best = dist;
					float4 u = prism_rec(prims, p, r + 2 + i);
					float ex = u.z - u.x, ez = u.w - u.y;
					n = conic ? (float3)(ez, -(ez * u.x - ex * u.y), -ex) * (q.y < 0.0f ? -1.0f : 1.0f)
					          : (float3)(ez, 0.0f, -ex);
				}
			}
		r += 2 + n_e;
	}
	return intersect_normal_to_world(p, n);
}

static inline bool prism_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float4 head = prism_rec(prims, p, 0);
	int flags = as_int(head.w);
	if ((flags & PRISM_FLAT) || !(q.y >= head.x && q.y < head.y))
		return false;
	if (flags & PRISM_CONIC) {
		if (fabs(q.y) < 1e-10f)
			return false;
		return prism_in_outline(prims, p, q.x / q.y, q.z / q.y);
	}
	return prism_in_outline(prims, p, q.x, q.z);
}
