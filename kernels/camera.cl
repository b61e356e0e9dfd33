/* camera.cl: POV-Ray 3.7's cameras, as its TracePixel::CreateCameraRay makes
 * their rays. x runs from -0.5 at the image's left edge to 0.5 at its right, y
 * from -0.5 at the bottom to 0.5 at the top. An integrator calls camera_ray,
 * which may make no ray (outside a fisheye's circle: POV-Ray's pixel is then
 * black), then camera_lens for focal blur, which also normalizes the direction.
 * The ray's direction is POV-Ray's before it normalizes it, since its focal
 * blur focuses each ray at that direction times a fixed length. */

/* The angle of (x, y) from the right, as POV-Ray's fisheye and omnimax
 * cameras take it (its image point for a camera's normal). */
static inline float camera_phi(float x, float y, float rad)
{
	if (rad == 0.0f)
		return 0.0f;
	return x < 0.0f ? M_PI_F - asin(y / rad) : asin(y / rad);
}

/* cos and sin of the angle of (x, y), with angle 0 at the centre. */
static inline float2 camera_polar(float x, float y, float rad)
{
	return rad > 0.0f ? (float2)(x, y) / rad : (float2)(1.0f, 0.0f);
}

/* The ray at angle theta from direction, turned by phi from right towards up:
 * the fisheye and omnimax cameras' rays. */
static inline float3 camera_sphere(float3 r, float3 u, float3 d, float2 phi, float theta)
{
	float st = sin(theta);
	return (phi.x * st) * r + (phi.y * st) * u + cos(theta) * d;
}

/* The fisheye: the circle of radius 1 in units of |right| and |up| about the
 * image's centre sees the angle right.w across; outside it, no ray. */
static inline bool camera_fisheye(global const dev_params *p, float x, float y, float lr, float lu,
                           float3 r, float3 u, float3 d, float3 *dir, float2 *xy)
{
	x *= 2.0f * lr;
	y *= 2.0f * lu;
	float rad = sqrt(x * x + y * y);
	if (rad > 1.0f)
		return false;
	*xy = (float2)(camera_phi(x, y, rad), rad * 0.5f * p->cam_right.w);
	*dir = camera_sphere(r, u, d, camera_polar(x, y, rad), xy->y);
	return true;
}

/* The omnimax projection (a polynomial fit of the dome's lens), its circle
 * moved to the image's top when the image is wider than tall, and nothing
 * more than 45 degrees below the axis. */
static inline bool camera_omnimax(float x, float y, float lr, float lu, float3 r, float3 u, float3 d, float3 *dir,
                                  float2 *xy)
{
	const float wide = 1.283458f;
	float aspect = lr / lu;
	x *= 2.0f;
	y *= 2.0f;
	if (aspect > wide) {
		x *= aspect / wide;
		y = (y - 1.0f) / wide + 1.0f;
	} else if (aspect > 1.0f) {
		y = (y - 1.0f) / aspect + 1.0f;
	} else {
		y /= aspect;
	}
	float rad = sqrt(x * x + y * y);
	if (rad > 1.0f)
		return false;
	float r2 = rad * rad;
	float theta = rad * (1.411269f + r2 * (-0.09439f + r2 * 0.25674f));
	float2 phi = camera_polar(x, y, rad);
	if (phi.y * sin(theta) < -cos(theta))   /* tan(135 degrees) * cos(theta) */
		return false;
	*xy = (float2)(camera_phi(x, y, rad), theta);
	*dir = camera_sphere(r, u, d, phi, theta);
	return true;
}

/* The panoramic camera (Graphics Gems III): 180 degrees across, from -right on
 * the left edge through direction to right, and up tan(180 y degrees); its
 * vectors keep their lengths. */
static inline float3 camera_panoramic(global const dev_params *p, float x, float y)
{
	float a = (0.5f - x) * M_PI_F, b = M_PI_F * y;
	float ty = tan(b);
	if (fabs(y) >= 0.5f || ty * y < 0.0f)   /* at the poles (past them, in float): POV-Ray's BOUND_HUGE */
		ty = copysign(2e10f, y);
	return cos(a) * p->cam_right.xyz + ty * p->cam_up.xyz + sin(a) * p->cam_direction.xyz;
}

/* v turned by angle a about the unit axis k, as POV-Ray's
 * Compute_Axis_Rotation_Transform turns points. */
static inline float3 camera_rotate(float3 v, float3 k, float a)
{
	float c = cos(a), s = sin(a);
	return c * v + s * cross(k, v) + ((1.0f - c) * dot(k, v)) * k;
}

/* The spherical camera: latitude y times the vertical angle (up.w) about
 * right, then longitude x times the horizontal angle (right.w) about up. */
static inline float3 camera_spherical(global const dev_params *p, float x, float y)
{
	float3 r = normalize(p->cam_right.xyz), u = normalize(p->cam_up.xyz);
	float3 v = camera_rotate(p->cam_direction.xyz, r, -y * p->cam_up.w);
	return camera_rotate(v, u, x * p->cam_right.w);
}

/* The types that turn their rays: unit right, up and direction, the lengths
 * of right and up as the image's proportions, the angle in right.w. xy is
 * POV-Ray's point of the ray on the image for a camera's normal: the angles or
 * lengths it makes the ray from. */
static inline bool camera_bent(global const dev_params *p, int type, float x, float y, float3 *o, float3 *dir,
                               float2 *xy)
{
	float lr = length(p->cam_right.xyz), lu = length(p->cam_up.xyz), angle = p->cam_right.w;
	float3 r = p->cam_right.xyz / lr, u = p->cam_up.xyz / lu, d = normalize(p->cam_direction.xyz);
	switch (type) {
	case CAMERA_FISHEYE:
		return camera_fisheye(p, x, y, lr, lu, r, u, d, dir, xy);
	case CAMERA_OMNIMAX:
		return camera_omnimax(x, y, lr, lu, r, u, d, dir, xy);
	case CAMERA_ULTRA_WIDE_ANGLE:   /* the vertical angle in proportion to |up| / |right| */
		x *= angle;
		y *= angle * lu / lr;
		*xy = (float2)(x, y);
		*dir = sin(x) * r + sin(y) * u + (cos(x) * cos(y)) * d;
		return true;
	case CAMERA_CYLINDER_1:   /* a vertical cylinder's axis along up, |up| high */
		*xy = (float2)(x * angle, y * lu);
		*dir = sin(xy->x) * r + xy->y * u + cos(xy->x) * d;
		return true;
	case CAMERA_CYLINDER_2:   /* a horizontal cylinder's axis along right, |right| wide */
		*xy = (float2)(x * lr, y * angle);
		*dir = xy->x * r + sin(xy->y) * u + cos(xy->y) * d;
		return true;
	case CAMERA_CYLINDER_3:   /* as 1, the rays parallel along up */
		*xy = (float2)(x * angle, y * lu);
		*o += xy->y * u;
		*dir = sin(xy->x) * r + cos(xy->x) * d;
		return true;
	default:                  /* CAMERA_CYLINDER_4: as 2, the rays parallel along right */
		*xy = (float2)(x * lr, y * angle);
		*o += xy->x * r;
		*dir = sin(xy->y) * u + cos(xy->y) * d;
		return true;
	}
}

/* The ray of the image point (px + jx, py + jy) in pixels from the top left:
 * false where the camera makes none. dir is not normalized. xy is the point
 * where a camera's normal perturbs the ray (POV-Ray's x0, y0 as its type
 * leaves them: the image point, or the angles made from it). */
static inline bool camera_ray(global const dev_params *p, int px, int py, float jx, float jy, float3 *o, float3 *dir,
                              float2 *xy)
{
	float x = ((float)px + jx) / (float)p->width - 0.5f;
	float y = 0.5f - ((float)py + jy) / (float)p->height;
	int type = (int)p->lens.z;
	*o = p->cam_location.xyz;
	*xy = (float2)(x, y);
	switch (type) {
	case CAMERA_PERSPECTIVE:
		*dir = p->cam_direction.xyz + x * p->cam_right.xyz + y * p->cam_up.xyz;
		return true;
	case CAMERA_ORTHOGRAPHIC:
		*o += x * p->cam_right.xyz + y * p->cam_up.xyz;
		*dir = p->cam_direction.xyz;
		return true;
	case CAMERA_PANORAMIC:
		*xy = (float2)((0.5f - x) * M_PI_F, M_PI_F * y);
		*dir = camera_panoramic(p, x, y);
		return true;
	case CAMERA_SPHERICAL:
		*xy = (float2)(x * p->cam_right.w, y * p->cam_up.w);
		*dir = camera_spherical(p, x, y);
		return true;
	default:
		return camera_bent(p, type, x, y, o, dir, xy);
	}
}

/* Focal blur, as POV-Ray's JitterCameraRay does it for every type: the ray
 * leaves a point of a lens in the plane of right and up about its origin,
 * toward the point dir * focal / |direction| from the origin (for the
 * perspective camera, the plane at the focal distance along direction).
 * POV-Ray moves the eye by aperture / 2 times a point of its sample grid,
 * which lies in a disc of radius 1/2: the lens's radius is aperture / 4.
 * Returns the origin and makes dir a unit vector. */
static inline float3 camera_lens(global const dev_params *p, float3 o, float3 *dir, float2 disc)
{
	float dl = length(p->cam_direction.xyz);
	if (p->lens.x > 0.0f && dl > 0.0f) {
		float3 focus = o + *dir * (p->lens.y / dl);
		o += 0.25f * p->lens.x * (disc.x * normalize(p->cam_right.xyz) + disc.y * normalize(p->cam_up.xyz));
		*dir = focus - o;
	}
	*dir = normalize(*dir);
	return o;
}
