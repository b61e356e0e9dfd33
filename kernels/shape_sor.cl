/* shape_sor.cl: sor and lathe (src/revolve.h): a profile of pieces revolved
 * about y in the shape's own space. Records: (rmax, hmin, hmax, pieces as an
 * int), (1 for a lathe as an int, 0, 0, 0), then two a piece:
 * (c0, c1, c2, c3), (h1, h2, hc, kind as an int: bit 0 a disc, bit 1 the side
 * -1), and for a lathe, one more a piece after those: (v at h1, v at h2, 0,
 * 0), POV-Ray's v at the piece's ends (a disc's: at its smaller and larger
 * radius). A curve's squared radius is ((c0 u + c1) u + c2) u + c3, u = h - hc,
 * for h1 <= h <= h2; a disc lies at height h1 with a squared radius from c0
 * to c1, and z is its side. The roots are found in double where
 * the device has it, as on the host: a quadratic in closed form, a cubic by
 * bisection between the roots of its derivative. */

#ifdef cl_khr_fp64
typedef double sor_real;
#else
typedef float sor_real;
#endif

static inline float4 sor_rec(global const dev_prim *prims, global const dev_prim *p, int i)
{
	return prims[p->link + i].a;
}

static inline sor_real sor_cubic(sor_real c0, sor_real c1, sor_real c2, sor_real c3, sor_real t)
{
	return ((c0 * t + c1) * t + c2) * t + c3;
}

/* The first root in (lo, hi) of the cubic g, else hi. */
static inline sor_real sor_first_root(sor_real g0, sor_real g1, sor_real g2, sor_real g3, sor_real lo, sor_real hi)
{
	if (!(lo < hi))
		return hi;
	if (g0 == 0) {
		sor_real r0, r1;
		if (g1 != 0) {
			sor_real disc = g2 * g2 - 4 * g1 * g3;
			if (disc < 0)
				return hi;
			sor_real q = -0.5 * (g2 + copysign(sqrt(disc), g2));
			r0 = q / g1;
			r1 = q != 0 ? g3 / q : r0;
		} else if (g2 != 0) {
			r0 = r1 = -g3 / g2;
		} else {
			return hi;
		}
		sor_real a = fmin(r0, r1), b = fmax(r0, r1);
		return a > lo && a < hi ? a : b > lo && b < hi ? b : hi;
	}
	sor_real cut[4];
	int nc = 1;
	cut[0] = lo;
	sor_real a = 3 * g0, b = 2 * g1, c = g2, disc = b * b - 4 * a * c;
	if (disc > 0) {
		sor_real q = -0.5 * (b + copysign(sqrt(disc), b)), r1 = q / a, r2 = q != 0 ? c / q : r1;
		sor_real x1 = fmin(r1, r2), x2 = fmax(r1, r2);
		if (x1 > lo && x1 < hi)
			cut[nc++] = x1;
		if (x2 > lo && x2 < hi)
			cut[nc++] = x2;
	}
	cut[nc] = hi;
	for (int i = 0; i < nc; i++) {
		sor_real l = cut[i], r = cut[i + 1];
		sor_real fl = sor_cubic(g0, g1, g2, g3, l), fr = sor_cubic(g0, g1, g2, g3, r);
		if (fl == 0 && l > lo)
			return l;
		if ((fl < 0) == (fr < 0) && fr != 0)
			continue;
		for (int k = 0; k < 80; k++) {
			sor_real m = 0.5 * (l + r);
			if (m <= l || m >= r)
				break;
			sor_real fm = sor_cubic(g0, g1, g2, g3, m);
			if ((fm < 0) == (fl < 0) && fm != 0) {
				l = m;
				fl = fm;
			} else {
				r = m;
			}
		}
		sor_real t = 0.5 * (l + r);
		if (t > lo && t < hi)
			return t;
	}
	return hi;
}

static inline float sor_intersect(float3 wo, float3 wd, global const dev_prim *prims, global const dev_prim *p,
                           float tmin, float tmax)
{
	float3 fo = intersect_to_local(p, wo), fd = intersect_dir_to_local(p, wd);
	float4 head = sor_rec(prims, p, 0);
	int n = as_int(head.w);
	sor_real ox = fo.x, oy = fo.y, oz = fo.z, dx = fd.x, dy = fd.y, dz = fd.z;
	sor_real R = (sor_real)head.x * (1 + 1e-6) + 1e-12, a = dx * dx + dz * dz, m = ox * dx + oz * dz;
	sor_real c = ox * ox + oz * oz - R * R, c0 = -INFINITY, c1 = INFINITY;
	if (a > 0) {
		sor_real disc = m * m - a * c;
		if (disc < 0)
			return tmax;
		c0 = (-m - sqrt(disc)) / a;
		c1 = (-m + sqrt(disc)) / a;
	} else if (c > 0) {
		return tmax;
	}
	if (dy != 0) {   /* the slab of all heights */
		sor_real t1 = ((sor_real)head.y - oy) / dy, t2 = ((sor_real)head.z - oy) / dy;
		c0 = fmax(c0, fmin(t1, t2) - 1e-6 * fabs(t2 - t1));
		c1 = fmin(c1, fmax(t1, t2) + 1e-6 * fabs(t2 - t1));
	}
	/* above the float after tmin: a root that rounds to tmin would be met again
	 * by a caller stepping on from it (CSG), forever */
	sor_real best = tmax, from = nextafter(tmin, INFINITY);
	if (!(c0 < best && c1 > from))
		return tmax;
	for (int i = 0; i < n; i++) {
		float4 cf = sor_rec(prims, p, 2 + 2 * i), hh = sor_rec(prims, p, 3 + 2 * i);
		if (as_int(hh.w) & 1) {   /* a disc */
			if (dy == 0)
				continue;
			sor_real t = ((sor_real)hh.x - oy) / dy, x = ox + t * dx, z = oz + t * dz, r2 = x * x + z * z;
			if (t > from && t < best && r2 >= cf.x && r2 <= cf.y)
				best = t;
			continue;
		}
		sor_real lo = fmax(from, c0), hi = fmin(best, c1);
		if (dy != 0) {
			sor_real t1 = ((sor_real)hh.x - oy) / dy, t2 = ((sor_real)hh.y - oy) / dy;
			lo = fmax(lo, fmin(t1, t2));
			hi = fmin(hi, fmax(t1, t2));
		} else if (oy < hh.x || oy > hh.y) {
			continue;
		}
		if (!(lo < hi))
			continue;
		sor_real f0 = cf.x, f1 = cf.y, f2 = cf.z, f3 = cf.w, u = oy - (sor_real)hh.z;
		sor_real g0 = f0 * dy * dy * dy, g1 = dy * dy * (3 * f0 * u + f1) - a;
		sor_real g2 = dy * (u * (3 * f0 * u + 2 * f1) + f2) - 2 * m;
		sor_real g3 = sor_cubic(f0, f1, f2, f3, u) - ox * ox - oz * oz;
		sor_real t = sor_first_root(g0, g1, g2, g3, lo, hi);
		if (t < hi)
			best = t;
	}
	return (float)best;
}

/* The piece the point is nearest to. */
static inline float3 sor_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	int n = as_int(sor_rec(prims, p, 0).w);
	float r2 = q.x * q.x + q.z * q.z, r = sqrt(r2), bestd = INFINITY;
	float3 nb = (float3)(0.0f, 1.0f, 0.0f);
	for (int i = 0; i < n; i++) {
		float4 cf = sor_rec(prims, p, 2 + 2 * i), hh = sor_rec(prims, p, 3 + 2 * i);
		float d;
		float3 nn;
		if (as_int(hh.w) & 1) {
			float rl = sqrt(fmax(cf.x, 0.0f)), rh = sqrt(fmax(cf.y, 0.0f));
			float out = fmax(fmax(rl - r, r - rh), 0.0f);
			d = sqrt((q.y - hh.x) * (q.y - hh.x) + out * out);
			nn = (float3)(0.0f, hh.z, 0.0f);
		} else {
			float y = clamp(q.y, hh.x, hh.y), u = y - hh.z, v = q.y - hh.z;
			float f = ((cf.x * u + cf.y) * u + cf.z) * u + cf.w;
			d = fabs(sqrt(fmax(f, 0.0f)) - r) + fabs(q.y - y);
			float k = (3.0f * cf.x * v * v + 2.0f * cf.y * v + cf.z) * 0.5f;
			nn = ((as_int(hh.w) & 2) ? -1.0f : 1.0f) * (float3)(q.x, -k, q.z);
		}
		if (d < bestd && dot(nn, nn) > 0.0f) {
			bestd = d;
			nb = nn;
		}
	}
	return intersect_normal_to_world(p, nb);
}

/* A sor's or lathe's uv, POV-Ray's: u the turn around y from +x toward +z; v
 * on the piece nearest the point (as sor_normal finds it). A sor's: on a curve
 * its share of the pieces below it and of its own height; on the base disc its
 * radius's share minus 1, on the cap 2 minus it. A lathe's (Lathe::UVCoord:
 * the spline segment's number plus its parameter, over the number of
 * segments): between the v its piece keeps at its ends, by the height on a
 * curve, by the radius on a disc. */
static inline float2 sor_uv(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	int n = as_int(sor_rec(prims, p, 0).w), curves = 0;
	bool lathe = as_int(sor_rec(prims, p, 1).x) != 0;
	float r = sqrt(q.x * q.x + q.z * q.z), bestd = INFINITY, v = 0.0f;
	for (int i = 0; i < n; i++)
		curves += !(as_int(sor_rec(prims, p, 3 + 2 * i).w) & 1);
	for (int i = 0; i < n; i++) {
		float4 cf = sor_rec(prims, p, 2 + 2 * i), hh = sor_rec(prims, p, 3 + 2 * i);
		float2 ends = lathe ? sor_rec(prims, p, 2 + 2 * n + i).xy : (float2)(0.0f);
		float d, vi;
		if (as_int(hh.w) & 1) {
			float rl = sqrt(fmax(cf.x, 0.0f)), rh = sqrt(fmax(cf.y, 0.0f));
			d = sqrt((q.y - hh.x) * (q.y - hh.x) + fmax(fmax(rl - r, r - rh), 0.0f) * fmax(fmax(rl - r, r - rh), 0.0f));
			if (lathe)
				vi = mix(ends.x, ends.y, rh > rl ? clamp((r - rl) / (rh - rl), 0.0f, 1.0f) : 0.0f);
			else
				vi = hh.z < 0.0f ? r / rh - 1.0f : 2.0f - r / rh;
		} else {
			float y = clamp(q.y, hh.x, hh.y), u = y - hh.z;
			float f = ((cf.x * u + cf.y) * u + cf.z) * u + cf.w;
			d = fabs(sqrt(fmax(f, 0.0f)) - r) + fabs(q.y - y);
			float t = (q.y - hh.x) / (hh.y - hh.x);
			vi = lathe ? mix(ends.x, ends.y, clamp(t, 0.0f, 1.0f)) : (t + (float)i) / (float)curves;
		}
		if (d < bestd) {
			bestd = d;
			v = vi;
		}
	}
	return (float2)(sphere_uv_about((float3)(q.x, 0.0f, q.z)).x, v);
}

static inline bool sor_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float4 head = sor_rec(prims, p, 0);
	int n = as_int(head.w);
	bool lathe = as_int(sor_rec(prims, p, 1).x) != 0;
	float y = q.y, r2 = q.x * q.x + q.z * q.z;
	if (!(y >= head.y && y <= head.z) || r2 > head.x * head.x)
		return false;
	bool in = false;
	for (int i = 0; i < n; i++) {
		float4 cf = sor_rec(prims, p, 2 + 2 * i), hh = sor_rec(prims, p, 3 + 2 * i);
		if (as_int(hh.w) & 1)
			continue;
		float u = y - hh.z, f = ((cf.x * u + cf.y) * u + cf.z) * u + cf.w;
		if (!lathe) {
			if (y >= hh.x && y <= hh.y)
				return r2 <= f;
		} else if (y >= hh.x && y < hh.y && f >= r2) {
			in = !in;
		}
	}
	return in;
}
