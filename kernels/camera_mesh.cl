/* camera_mesh.cl: the camera ray an integrator starts from. POV-Ray's
 * mesh_camera reads the rays lower_camera_mesh.c made for each pixel; the
 * other types are camera.cl's. With several rays a pixel, a sample's
 * sub-pixel place picks its ray, so the samples share the rays out evenly. */
static inline bool camera_view(const scene_data *sc, int px, int py, float jx, float jy, float3 *o, float3 *dir,
                               float2 *xy)
{
	global const dev_params *p = sc->p;
	*xy = (float2)(0.0f);   /* POV-Ray's image point of a mesh camera's ray */
	if ((int)p->lens.z != CAMERA_MESH)
		return camera_ray(p, px, py, jx, jy, o, dir, xy);
	int rays = (int)p->lens.w;
	int r = clamp((int)(jx * (float)rays), 0, rays - 1);
	global const float4 *ray = sc->camera_rays + (((size_t)r * p->height + py) * p->width + px) * 2;
	if (ray[0].w == 0.0f)
		return false;   /* no face there: POV-Ray's pixel is black */
	*o = ray[0].xyz;
	*dir = ray[1].xyz;
	return true;
}

/* How far a camera ray looks for its first hit: a mesh_camera's max_distance
 * (POV-Ray's TraceRay maxDepth for the camera's rays; 0 is no limit), which
 * lower_camera_mesh.c keeps in every ray's w. Both integrators normalise the
 * direction, so it is a distance, as in POV-Ray. */
static inline float camera_max_distance(const scene_data *sc)
{
	if ((int)sc->p->lens.z != CAMERA_MESH)
		return INFINITY;
	float m = sc->camera_rays[1].w;
	return m > 0.0f ? m : INFINITY;
}
