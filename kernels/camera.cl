/* camera.cl: POV-Ray's perspective camera. A primary ray goes from the location
 * along direction + sx * right + sy * up, with sx in [-0.5, 0.5] from left to right
 * and sy in [-0.5, 0.5] from bottom to top of the image. */

inline float3 camera_ray_dir(global const dev_params *p, int px, int py, float jx, float jy)
{
	float sx = ((float)px + jx) / (float)p->width - 0.5f;
	float sy = 0.5f - ((float)py + jy) / (float)p->height;
	float3 d = p->cam_direction.xyz + sx * p->cam_right.xyz + sy * p->cam_up.xyz;
	return normalize(d);
}
