/* sky_light.cl: next-event estimation of the sky (the path tracer, when
 * dev_params.sky_sampled): a direction drawn from the sky's image by
 * importance (kernels/sky_sample.cl), weighted against BSDF sampling by the
 * power heuristic; a bounce ray that leaves the scene takes the other weight
 * (integrator_path.cl). The radiance is texture_sky's, looked up as every ray
 * that leaves the scene looks it up, so the image's interpolation and the
 * background under it are the sky's own, and the table need only be close. */

/* One sample of the sky seen from x above the surface (normals ng, n; wo
 * toward the viewer); dim: five dimensions. The shadow ray stops at any
 * surface, as light_emitters' do: paths through transparent surfaces find
 * the sky by BSDF sampling, whose weight there is 1. */
static inline float3 light_sky(const scene_data *sc, const bsdf *m, const material_lobes *lobes, float3 x, float3 ng,
                        float3 n, float3 wo, uint key, uint dim, media_stack ms, int solids)
{
	global const dev_params *p = sc->p;
	float pdf_sky, pdf_bsdf;
	float3 wi = sky_sample(sc->sky_dist, sc->sky_cdf, rng_uniform(key, dim), rng_uniform(key, dim + 1),
	                       rng_uniform(key, dim + 2), rng_uniform(key, dim + 3), &pdf_sky);
	float3 f = material_eval(m, lobes, n, wo, wi, &pdf_bsdf);
	if (!(pdf_sky > 0.0f) || dot(ng, wi) <= 0.0f || (f.x <= 0.0f && f.y <= 0.0f && f.z <= 0.0f))
		return (float3)(0.0f);
	sc->counts[COUNT_RAYS + RAY_SHADOW]++;
	if (traverse_any(sc, sc->nodes, sc->prims, p->n_prims, p->n_planes, x, wi, 0.0f, INFINITY, sc->counts))
		return (float3)(0.0f);
	/* what a bounce ray leaving the scene along wi goes through: the fogs
	 * (their glow is the path's, unweighted), the rainbows and the media around x */
	float3 tr = solids == 0 && p->n_fogs > 0 ? fog_segment(sc, x, wi, INFINITY, true).att : (float3)(1.0f);
	if (solids == 0 && p->n_rainbows > 0)
		tr *= rainbow_segment(sc, wi, INFINITY, rng_hash(key ^ rng_hash(dim + 5u))).att;
	media_list l = media_list_at(sc, &ms, solids);
	tr *= media_transmittance(sc, &l, x, wi, INFINITY, key, dim + 4);
	return tr * texture_sky(sc, wi, false) * f * (light_power_heuristic(pdf_sky, pdf_bsdf) / pdf_sky);
}
