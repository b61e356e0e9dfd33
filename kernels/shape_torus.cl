/* shape_torus.cl: POV-Ray's torus, kept as the map from world space to the
 * torus of major radius 1 around the y axis, the minor radius k (the minor
 * over the major) in its PRIM_DATA record. A minor radius above the major is
 * POV-Ray 3.7's spindle torus: every root is a surface (src/shape_torus.c).
 *
 * The ray's roots are those of a quartic. Float loses them at grazing rays,
 * and a closed formula (Ferrari's) loses them to cancellation, so the quartic
 * is solved in double where the device has it, by kernels/roots.cl. */

static inline float torus_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
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
	/* the first root whose float is past tmin: a root rounded down onto
	 * tmin is the one a CSG's last step stopped at */
	real a = 0, u;
	for (int i = 0; i < 4 && roots_find(c, 4, a, L, &u, 1) == 1; i++) {
		float t = (float)((s0 + u) / len);
		if (t > tmin)
			return t < tmax ? t : tmax;
		a = u;
	}
	return tmax;
}

/* The geometric normal, the quartic's gradient: from the nearest point M of
 * the circle, P - M, or on a spindle torus's inner surface (inside the sphere
 * through the spindle's tips), where the tube around the far point -M makes
 * the surface, -(P + M). */
static inline float3 torus_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
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
static inline float3 torus_shading_normal(global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float rho = sqrt(q.x * q.x + q.z * q.z);
	float3 m = rho > 1e-10f ? (float3)(q.x / rho, 0.0f, q.z / rho) : (float3)(0.0f);
	return intersect_normal_to_world(p, q - m);
}

/* POV-Ray's uv: u the turn around y (from -x, clockwise seen from +y), v the
 * turn around the tube from its inner side; the angles do not depend on the
 * radii, so the torus of major radius 1 gives them. */
static inline float2 torus_uv(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float3 q = intersect_to_local(p, x);
	float u = 1.0f - (atan2(q.z, q.x) + M_PI_F) / (2.0f * M_PI_F);
	float r = sqrt(q.x * q.x + q.z * q.z) - 1.0f;
	return (float2)(u, (atan2(q.y, r) + M_PI_F) / (2.0f * M_PI_F));
}

static inline bool torus_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	float k = intersect_data(prims, p).x;
	float3 q = intersect_to_local(p, x);
	float r = sqrt(q.x * q.x + q.z * q.z) - 1.0f;
	return r * r + q.y * q.y <= k * k;
}
