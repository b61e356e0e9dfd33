/* visibility.cl: what a ray sees past the surfaces that let it through, one
 * helper for both integrators: the closest surface a kind of ray may see
 * (POV-Ray's no_image, no_reflection), and how much of a light_source's light
 * reaches a point through filtering and transmitting surfaces, as POV-Ray's
 * shadow rays let it through (no_shadow objects cast none). */

/* The scene object a hit belongs to: a mesh's triangles are its instance's. */
static inline int visibility_object(const scene_data *sc, traverse_hit h)
{
	return h.inst >= 0 ? sc->prims[h.inst].object : sc->prims[h.prim].object;
}

/* The closest surface along (o, d) in (tmin, tmax) whose object carries none of
 * the flags in skip. */
static inline traverse_hit visibility_closest(const scene_data *sc, float3 o, float3 d, float tmin, float tmax, int skip,
                                       int kind)
{
	for (;;) {
		traverse_hit h = traverse_closest(sc, sc->nodes, sc->prims, sc->p->n_prims, sc->p->n_planes, o, d, tmin, tmax,
		                                  sc->counts, kind);
		if (h.prim < 0 || !(sc->objects[visibility_object(sc, h)] & skip))
			return h;
		tmin = h.t;
	}
}

/* POV-Ray's interior fade over a distance t travelled inside. */
static inline float3 visibility_fade(global const dev_material *m, float t)
{
	float fd = m->interior.y, fp = m->interior.z;
	float3 fc = m->fade_color.xyz;
	if (fabs(fd) <= 1e-10f || fp <= 0.0f)
		return (float3)(1.0f);
	if (fp >= 1000.0f)
		return exp(-((float3)(1.0f) - fc) * (t / fd));
	return fc + ((float3)(1.0f) - fc) / (1.0f + pow(t / fd, fp));
}

#define VISIBILITY_CROSSINGS 32   /* transparent surfaces a shadow ray passes, at most */

/* What of colour, a light's, reaches o from along l in (tmin, tmax): each
 * surface between filters it by pigment * filter + transmit (texture_filter:
 * over layers and blended textures), and by its
 * interior's fade where the ray leaves an inside; an opaque surface stops it
 * (POV-Ray's TracePointLightShadowRay). In a scene where nothing lets shadow
 * rays through, the first surface met stops them, found by an any-hit query. */
static inline float3 visibility_shadow(const scene_data *sc, float3 o, float3 l, float tmin, float tmax, float3 colour)
{
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	if (!(sc->p->scene_flags & SCENE_SHADOWS_PASS))
		return traverse_any(sc, sc->nodes, sc->prims, sc->p->n_prims, sc->p->n_planes, o, l, tmin, tmax, sc->counts)
		     ? (float3)(0.0f) : colour;
	float start = 0.0f;
	for (int i = 0; i < VISIBILITY_CROSSINGS; i++) {
		traverse_hit h = visibility_closest(sc, o, l, tmin, tmax - start, OBJECT_NO_SHADOW, RAY_SHADOW);
		if (h.prim < 0)
			return colour;
		shading_point sp = texture_point(sc, h, o, l);
		float pass;
		float3 filter = texture_filter(sc, &sp, &pass);
		if (pass < sc->p->classic.w)
			return (float3)(0.0f);
		colour *= filter;
		if (!sp.entering)   /* leaving an object: its interior faded the light */
			colour *= visibility_fade(sp.m, h.t);
		o += h.t * l;
		start += h.t;
		tmin = fmax(tmin, sp.eps);   /* past the surface just crossed */
		sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	}
	return (float3)(0.0f);
}
