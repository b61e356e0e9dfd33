/* pattern.cl: POV-Ray's patterns, evaluated on the device (see shared.h,
 * dev_pattern). pattern_value gives a point's value in the pattern's space:
 * a continuous pattern's in [0, 1], a discrete pattern's list index. */

/* POV-Ray's checker: the parity of the sum of the point's integer cells, with
 * its small offset so that faces on integer planes are not split. */
inline float pattern_checker(float3 p)
{
	float3 q = floor(p + (float3)(-1e-6f, 1e-6f, 1e-6f));   /* POV-Ray's SMALL_TOLERANCE */
	int s = (int)q.x + (int)q.y + (int)q.z;
	return (float)(s & 1);
}

/* gradient: the fraction of the point's position along the axis. */
inline float pattern_gradient(float3 p, float3 axis)
{
	float v = dot(p, axis);
	return v - floor(v);
}

/* frequency, phase and the ramp wave of a continuous pattern. */
inline float pattern_wave(global const dev_pattern *pt, float v)
{
	if (pt->frequency != 0.0f)
		v = fmod(v * pt->frequency + pt->phase, 1.00001f);
	if (v < 0.0f)
		v -= floor(v);
	return v;
}

inline float pattern_value(global const dev_pattern *pt, global const dev_warp *warps, float3 p, float3 n, float3 d)
{
	switch (pt->kind) {
	case PATTERN_CHECKER: return pattern_checker(p);
	case PATTERN_GRADIENT: return pattern_wave(pt, pattern_gradient(p, pt->params[0].xyz));
	default: return 0.0f;
	}
}
