/* rainbow.cl: POV-Ray 3.7's rainbow (Trace::ComputeRainbow), for both integrators.
 *
 * A rainbow is a colour seen in the directions around its antisolar vector
 * (direction): a ray whose angle to it is within the band (angle, width)
 * reads the colour_map at its place across the band, and that colour is
 * laid over what the ray brought back, the more the farther the ray went
 * (exp(-depth / distance) is what shows through, never less than the
 * colour's transmit, and more toward the ends of an arc_angle after its
 * falloff_angle); the colour's filter tints what shows through. Several
 * rainbows that cover a ray are averaged, as POV-Ray averages them. A ray
 * that leaves the scene goes FOG_HUGE, POV-Ray's BOUND_HUGE. Like the fog,
 * only rays outside solid objects see rainbows, and shadow rays none. */

/* What the rainbows do to the light coming back along a ray: it becomes
 * add + att * light, and the alpha channel's transmittance is multiplied
 * by transm. */
typedef struct {
	float3 att, add;
	float transm;
} rainbow_effect;

/* POV-Ray's fade toward the end of an arc: smooth from 0 at falloff_angle
 * to 1 at arc_angle. */
static inline float rainbow_fade(global const dev_rainbow *r, float angle)
{
	if (!(r->falloff_width > 0.0f) || angle <= r->falloff_angle)
		return 0.0f;
	float f = (angle - r->falloff_angle) / r->falloff_width;
	return (3.0f - 2.0f * f) * f * f;
}

/* Every rainbow over a ray of unit direction d that went t (INFINITY: it
 * left the scene); key draws each rainbow's jitter (POV-Ray's is random too). */
static inline rainbow_effect rainbow_segment(const scene_data *sc, float3 d, float t, uint key)
{
	rainbow_effect e = { (float3)(0.0f), (float3)(0.0f), 1.0f };
	float depth = fmin(t, FOG_HUGE);
	int n = 0;
	for (int i = 0; i < sc->p->n_rainbows; i++) {
		global const dev_rainbow *r = &sc->rainbows[i];
		/* the ray's angle from up, in the plane square to the direction */
		float x = dot(d, r->right.xyz), y = dot(d, r->up.xyz);
		float l = x * x + y * y;
		if (l > 0.0f)
			y /= sqrt(l);
		float angle = fabs(acos(clamp(y, -1.0f, 1.0f)));
		float cos_d = dot(d, r->direction.xyz);
		if (angle > r->arc_angle || cos_d < 0.0f)
			continue;
		float index = (acos(fmin(cos_d, 1.0f)) - r->direction.w) / r->up.w;
		if (r->jitter > 0.0f)
			index += (2.0f * rng_uniform(key, (uint)i) - 1.0f) * r->jitter;
		if (!(index >= 0.0f && index < 1.0f))   /* POV-Ray's 1 - EPSILON, in single precision */
			continue;
		pigment_colour c = texture_pigment_tree(sc, r->pattern, (float3)(index, 0.0f, 0.0f), (float2)(0.0f), -d, d);
		float fade = rainbow_fade(r, angle);
		float k = fmax(exp(-depth / r->right.w), fade * (1.0f - c.transmit) + c.transmit);
		float ki = 1.0f - k, f = c.filter * ki;
		e.att += k * ((1.0f - f) + f * c.rgb);
		e.add += ki * c.rgb;
		e.transm *= k * c.transmit;
		n++;
	}
	if (n == 0)
		return (rainbow_effect){ (float3)(1.0f), (float3)(0.0f), 1.0f };
	e.att /= (float)n;
	e.add /= (float)n;
	return e;
}
