/* shape_disc.cl: POV-Ray's disc (src/shape_disc.c), kept as the map from world
 * space to the unit disc in z = 0, its normal +z, about its centre; its
 * PRIM_DATA records: x the square of the hole's radius (over the disc's), then
 * the centre (xyz). Its inside is z < 0. */

static inline float3 disc_local(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_to_local_about(p, prims[p->link + 1].a.xyz, x);
}

/* The ray starts from its point nearest the centre, so the distance from the
 * centre keeps its precision when the disc is far away. */
static inline float disc_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                            float tmin, float tmax)
{
	float3 oo = disc_local(prims, p, o), dd = intersect_dir_to_local(p, d);
	if (dd.z == 0.0f)
		return tmax;
	float ts = -dot(oo, dd) / dot(dd, dd);
	oo += ts * dd;
	float s = -oo.z / dd.z, t = ts + s;
	if (!(t > tmin && t < tmax))
		return tmax;
	float2 w = oo.xy + s * dd.xy;
	float r2 = dot(w, w);
	return r2 >= intersect_data(prims, p).x && r2 <= 1.0f ? t : tmax;
}

static inline float3 disc_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return intersect_normal_to_world(p, (float3)(0.0f, 0.0f, 1.0f));
}

static inline bool disc_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return disc_local(prims, p, x).z < 0.0f;
}

/* As an emitter (shape.cl's shape_emit_sample and shape_emit_pdf): a point
 * uniform over its ring in its own space (the square of the radius uniform
 * between the hole's and 1), which is uniform over its area in world space
 * too, since the map is affine and the disc flat: an ellipse's or a
 * parallelogram's disc under any scale or shear is sampled as well as a
 * round one. */
static inline bool disc_emit_sample(global const dev_prim *prims, global const dev_prim *p, float3 x, float u1,
                                    float u2, float3 *wi, float3 *pos)
{
	float h2 = intersect_data(prims, p).x, r = sqrt(h2 + u1 * (1.0f - h2)), phi = 2.0f * M_PI_F * u2;
	*pos = intersect_to_world_about(p, prims[p->link + 1].a.xyz, (float3)(r * cos(phi), r * sin(phi), 0.0f));
	*wi = normalize(*pos - x);
	return true;
}

/* The density of the point t along wi from x in solid angle, pick times it:
 * one over the ring's area in world space. */
static inline float disc_emit_pdf(global const dev_prim *prims, global const dev_prim *p, float3 x, float3 wi,
                                  float t, float pick, float area)
{
	float3 nz = (float3)(0.0f, 0.0f, 1.0f);
	float ring = M_PI_F * (1.0f - intersect_data(prims, p).x) * intersect_area_scale(p, nz);
	return intersect_area_to_solid_angle(pick / ring, intersect_normal_to_world(p, nz), wi, t);
}
