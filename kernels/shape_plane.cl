/* shape_plane.cl: POV-Ray's plane, the half-space below it being its inside.
 * a.xyz is the unit normal, a.w the distance of the plane from the origin along it. */

static inline float plane_intersect(float3 o, float3 d, global const dev_prim *prims, global const dev_prim *p,
                             float tmin, float tmax)
{
	float dn = dot(p->a.xyz, d);
	if (dn == 0.0f)
		return tmax;
	float t = (p->a.w - dot(p->a.xyz, o)) / dn;
	return t > tmin && t < tmax ? t : tmax;
}

static inline float3 plane_normal(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return p->a.xyz;
}

static inline bool plane_inside(global const dev_prim *prims, global const dev_prim *p, float3 x)
{
	return dot(p->a.xyz, x) < p->a.w;
}
