/* camera.cl: POV-Ray's perspective and orthographic cameras. A perspective
 * primary ray goes from the location along direction + sx * right + sy * up, with
 * sx in [-0.5, 0.5] from left to right and sy in [-0.5, 0.5] from bottom to top
 * of the image; an orthographic one from location + sx * right + sy * up along
 * direction. An integrator calls camera_ray_dir, then camera_lens, which gives
 * the ray's origin and changes its direction for focal blur and the
 * orthographic camera. */

inline float3 camera_ray_dir(global const dev_params *p, int px, int py, float jx, float jy)
{
	float sx = ((float)px + jx) / (float)p->width - 0.5f;
	float sy = 0.5f - ((float)py + jy) / (float)p->height;
	float3 d = p->cam_direction.xyz + sx * p->cam_right.xyz + sy * p->cam_up.xyz;
	return normalize(d);
}

/* Focal blur: the ray leaves a point of a lens of diameter aperture in the plane
 * of right and up, toward where the pinhole ray meets the focal plane (through
 * focal_point, facing direction). */
/* The orthographic camera from the perspective ray dir of camera_ray_dir: where
 * that ray meets the plane of right and up through the tip of direction is
 * direction + sx * right + sy * up, which gives the pixel's offset back. */
inline float3 camera_parallel(global const dev_params *p, float3 *dir)
{
	float3 n = cross(p->cam_right.xyz, p->cam_up.xyz);
	float t = dot(n, p->cam_direction.xyz) / dot(n, *dir);
	float3 o = p->cam_location.xyz + t * *dir - p->cam_direction.xyz;
	*dir = normalize(p->cam_direction.xyz);
	return o;
}

inline float3 camera_lens(global const dev_params *p, float3 *dir, float2 disc)
{
	float3 o = p->cam_location.xyz;
	if (p->lens.z > 0.0f)
		return camera_parallel(p, dir);   /* no focal blur: a parallel view is sharp */
	if (p->lens.x <= 0.0f)
		return o;
	float3 axis = normalize(p->cam_direction.xyz);
	float3 focus = o + *dir * (p->lens.y / dot(*dir, axis));
	o += 0.5f * p->lens.x * (disc.x * normalize(p->cam_right.xyz) + disc.y * normalize(p->cam_up.xyz));
	*dir = normalize(focus - o);
	return o;
}
