/* material.cl: the path tracer's layered BSDF, made from a dev_material (shared.h).
 *
 * From the top: a clear coat (GGX, Schlick's Fresnel), a reflection layer (a
 * mirror, or GGX when rough), a dielectric interface that transmits (Fresnel,
 * refraction, total internal reflection), and a Lambertian base. Each layer takes
 * its share of what the layers above let through, evaluated at the outgoing
 * direction, so the shares sum to at most 1 and every lobe reflects at most what
 * it receives: no material returns more energy than it receives. */

/* The path tracer's view of a material at one point, made by material_bsdf
 * from POV-Ray's finish and the pigment evaluated there. */
typedef struct {
	float3 diffuse;     /* Lambertian albedo of the opaque part */
	float3 emission;    /* emitted radiance, both sides */
	float4 reflect;     /* rgb: reflection at normal incidence; w: GGX alpha, 0 for a mirror */
	float4 reflect_max; /* rgb: reflection at grazing incidence; w: falloff exponent,
	                     * or -1: Fresnel's equations with the ior decide between the two */
	float4 transmit;    /* rgb: tint of transmitted light; w: ior (1: no refraction) */
	float4 absorb;      /* rgb: absorption per unit length inside; w: transmitted fraction */
	float4 coat;        /* x: coat strength, y: coat GGX alpha, z: coat reflectance at normal incidence */
	float4 irid;        /* x: irid's amount (0: none), y: its film thickness at the point (the
	                     * caller's, finish_irid_thickness); rgb of irid_wl: the wavelengths */
	float3 irid_wl;
} bsdf;

/* POV-Ray's roughness is a Blinn exponent's reciprocal, phong_size a Phong
 * exponent (about a quarter of Blinn's); a Blinn exponent e matches GGX with
 * alpha = sqrt(2 / (e + 2)) (Walter et al. 2007). */
static inline float material_alpha_from_blinn(float e)
{
	return clamp(sqrt(2.0f / (e + 2.0f)), 0.01f, 1.0f);
}

/* POV-Ray's finish and interior with the pigment at a point, as a layered BSDF
 * (eclat-scene(5), HOW MATERIALS ARE RENDERED): the opaque share of the pigment
 * is diffuse, filter and transmit are transmission tinted by the pigment's
 * filter share, reflection is a mirror or GGX layer tinted by metallic, and
 * phong or specular a clear coat. */
static inline bsdf material_bsdf(global const dev_material *m, float3 rgb, float filter, float transmit)
{
	bsdf d;
	float t = clamp(filter + transmit, 0.0f, 1.0f);
	float3 tint = t > 0.0f ? clamp((filter * rgb + transmit) / t, 0.0f, 1.0f) : (float3)(1.0f);
	float metallic = fmax(m->terms.y, m->terms.z);
	float3 metal = (1.0f - metallic) + metallic * rgb;
	float ior = m->interior.x > 0.0f ? m->interior.x : 1.0f;
	float fd = m->interior.y;
	bool fade = fd > 0.0f && m->interior.z > 0.0f;
	float blinn = m->highlight.w > 0.0f ? m->highlight.w : 1e6f;   /* 1 / roughness */
	d.diffuse = clamp(rgb * m->emission.w, 0.0f, 1.0f) * (1.0f - t);
	d.emission = rgb * m->emission.xyz;
	d.reflect = (float4)(clamp(m->reflection.xyz * metal, 0.0f, 1.0f),
	                     m->flags & MATERIAL_ROUGH ? material_alpha_from_blinn(blinn) : 0.0f);
	d.reflect_max = (float4)(clamp(m->reflection_max.xyz * metal, 0.0f, 1.0f),
	                         m->terms.w > 0.0f ? -1.0f : m->reflection.w);
	d.transmit = (float4)(tint, ior);
	d.absorb = (float4)(fade ? (1.0f - clamp(m->fade_color.xyz, 0.0f, 1.0f)) / fd : (float3)(0.0f), t);
	float phong = m->highlight.x, specular = m->highlight.z;
	float alpha = phong >= specular ? material_alpha_from_blinn(4.0f * m->highlight.y)
	                                : material_alpha_from_blinn(blinn);
	d.coat = (float4)(clamp(fmax(phong, specular), 0.0f, 1.0f), alpha, 0.04f, 0.0f);   /* 0.04: ior 1.5 */
	d.irid = (float4)(m->irid.x, m->irid.y, 0.0f, 0.0f);
	d.irid_wl = m->irid_wavelength.xyz;
	return d;
}

/* irid's tint of what the surface reflects from wi toward wo, as the Whitted
 * integrator tints each light and the reflected ray; never below 0, which a
 * BSDF cannot be. */
static inline float3 material_irid(const bsdf *m, float3 n, float3 wo, float3 wi)
{
	if (m->irid.x <= 0.0f)
		return (float3)(1.0f);
	return fmax(finish_irid_tint(m->irid.x, m->irid.y, m->irid_wl, n, wi, wo), 0.0f);
}

/* A direction about n with density cos(theta) / pi. The angle about n is
 * 2 pi u2, taken by sinpi and cospi of 2 u2: sin and cos of an angle up to
 * 2 pi go through PoCL's general argument reduction, sinpi's needs none
 * (make bench's render: 6% more paths a second). */
static inline float3 material_sample_cosine(float3 n, float u1, float u2)
{
	float3 t, b;
	intersect_basis(n, &t, &b);
	float r = sqrt(u1);
	return normalize(r * cospi(2.0f * u2) * t + r * sinpi(2.0f * u2) * b + sqrt(fmax(0.0f, 1.0f - u1)) * n);
}

static inline float material_luminance(float3 c)
{
	return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

/* Unpolarised Fresnel reflectance of a dielectric interface; cos_i > 0 is on the
 * incident side and eta = n_transmitted / n_incident. 1 under total internal reflection. */
static inline float material_fresnel(float cos_i, float eta)
{
	float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
	if (sin2_t >= 1.0f)
		return 1.0f;
	float cos_t = sqrt(1.0f - sin2_t);
	float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
	float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
	return 0.5f * (rs * rs + rp * rp);
}

static inline float material_schlick(float cos_i, float f0)
{
	float m = 1.0f - cos_i, m2 = m * m;
	return f0 + (1.0f - f0) * m2 * m2 * m;
}

/* GGX reflection without Fresnel: returns f * cos(theta_i) and its pdf when
 * sampled by material_ggx_sample (the distribution of normals times n.h). */
static inline float material_ggx_eval(float3 n, float3 wo, float3 wi, float alpha, float *pdf)
{
	float no = dot(n, wo), ni = dot(n, wi);
	*pdf = 0.0f;
	if (no <= 0.0f || ni <= 0.0f)
		return 0.0f;
	float3 h = normalize(wo + wi);
	float nh = dot(n, h), oh = dot(wo, h), a2 = alpha * alpha;
	float t = nh * nh * (a2 - 1.0f) + 1.0f;
	float d = a2 / (M_PI_F * t * t);
	float g1o = 2.0f * no / (no + sqrt(a2 + (1.0f - a2) * no * no));
	float g1i = 2.0f * ni / (ni + sqrt(a2 + (1.0f - a2) * ni * ni));
	*pdf = d * nh / (4.0f * oh);
	return d * g1o * g1i / (4.0f * no);
}

static inline float3 material_ggx_sample(float3 n, float3 wo, float alpha, float u1, float u2)
{
	float3 t, b;
	intersect_basis(n, &t, &b);
	float cos_t = sqrt((1.0f - u1) / (1.0f + (alpha * alpha - 1.0f) * u1));
	float sin_t = sqrt(fmax(0.0f, 1.0f - cos_t * cos_t));
	float3 h = sin_t * cospi(2.0f * u2) * t + sin_t * sinpi(2.0f * u2) * b + cos_t * n;
	return 2.0f * dot(wo, h) * h - wo;
}

/* The layers' shares at one outgoing direction, and the probabilities of
 * sampling each (proportional to the shares' luminance). */
typedef struct {
	float3 coat, refl, trans, diff;
	float p_coat, p_refl, p_trans, p_diff;
} material_lobes;

static inline material_lobes material_lobes_at(const bsdf *m, float cos_o, bool entering)
{
	material_lobes l;
	float wc = m->coat.x * material_schlick(cos_o, m->coat.z);
	/* Most surfaces reflect the same at every angle (reflect_max == reflect, often 0):
	 * they skip the falloff, whose pow was a sixth of the bench scene's time on PoCL. */
	float3 r = clamp(m->reflect.xyz, 0.0f, 1.0f);
	if (any(m->reflect_max.xyz != m->reflect.xyz)) {
		float k = m->reflect_max.w < 0.0f
		        ? material_fresnel(cos_o, entering ? m->transmit.w : 1.0f / m->transmit.w)
		        : pow(1.0f - cos_o, m->reflect_max.w);
		r = clamp(m->reflect.xyz + (m->reflect_max.xyz - m->reflect.xyz) * k, 0.0f, 1.0f);
	}
	float3 rest = (1.0f - wc) * (1.0f - r);
	l.coat = (float3)(wc);
	l.refl = (1.0f - wc) * r;
	l.trans = rest * m->absorb.w;
	l.diff = rest * m->diffuse;
	float pc = wc, pr = material_luminance(l.refl), pt = material_luminance(l.trans);
	float pd = material_luminance(l.diff), sum = pc + pr + pt + pd;
	float inv = sum > 0.0f ? 1.0f / sum : 0.0f;
	l.p_coat = pc * inv;
	l.p_refl = pr * inv;
	l.p_trans = pt * inv;
	l.p_diff = pd * inv;
	return l;
}

/* f * cos(theta_i) of the lobes that are not a single direction (diffuse, coat,
 * rough reflection), and the pdf of sampling wi by material_sample. */
static inline float3 material_eval(const bsdf *m, const material_lobes *l, float3 n,
                            float3 wo, float3 wi, float *pdf)
{
	float ni = dot(n, wi);
	*pdf = 0.0f;
	if (ni <= 0.0f)
		return (float3)(0.0f);
	float3 f = l->diff * (ni / M_PI_F);
	float p = l->p_diff * (ni / M_PI_F), lobe_pdf;
	if (l->p_coat > 0.0f) {
		f += l->coat * material_ggx_eval(n, wo, wi, m->coat.y, &lobe_pdf);
		p += l->p_coat * lobe_pdf;
	}
	if (l->p_refl > 0.0f && m->reflect.w > 0.0f) {
		f += l->refl * material_ggx_eval(n, wo, wi, m->reflect.w, &lobe_pdf);
		p += l->p_refl * lobe_pdf;
	}
	*pdf = p;
	return f * material_irid(m, n, wo, wi);
}

typedef struct {
	float3 wi;
	float3 weight;     /* f * cos / pdf: what the path's throughput is multiplied by */
	float pdf;         /* 0 for a single direction (mirror, smooth glass): no MIS */
	int transmitted;   /* 1: the ray crossed the surface */
} material_sample_t;

/* Refraction of wo (pointing away from the surface, n on its side) with
 * eta = n_transmitted / n_incident; the caller has ruled out total reflection. */
static inline float3 material_refract(float3 wo, float3 n, float cos_o, float eta)
{
	float cos_t = sqrt(fmax(0.0f, 1.0f - (1.0f - cos_o * cos_o) / (eta * eta)));
	return normalize(-wo / eta + (cos_o / eta - cos_t) * n);
}

/* Chooses a layer by u.x, then a direction with u.y, u.z. weight 0: absorbed. */
static inline material_sample_t material_sample(const bsdf *m, const material_lobes *l,
                                         float3 n, float3 wo, bool entering, float3 u)
{
	material_sample_t s = { (float3)(0.0f), (float3)(0.0f), 0.0f, 0 };
	float cos_o = dot(n, wo);
	/* the layers' intervals of u.x: [0, c0) coat, [c0, c1) reflection,
	 * [c1, c2) transmission, [c2, 1) diffuse */
	float c0 = l->p_coat, c1 = c0 + l->p_refl, c2 = c1 + l->p_trans;
	if (u.x >= c0 && u.x < c1 && m->reflect.w == 0.0f) {
		s.wi = 2.0f * cos_o * n - wo;          /* the mirror */
		s.weight = l->refl / l->p_refl * material_irid(m, n, wo, s.wi);
		return s;
	}
	if (u.x >= c1 && u.x < c2) {
		float3 tint = m->transmit.xyz, w = l->trans / l->p_trans;
		float ior = m->transmit.w;
		if (ior == 1.0f) {                     /* transmit without refraction */
			s.wi = -wo;
			s.weight = w * tint;
			s.transmitted = 1;
			return s;
		}
		float eta = entering ? ior : 1.0f / ior;
		float f = material_fresnel(cos_o, eta);
		if (u.y < f) {
			s.wi = 2.0f * cos_o * n - wo;
			s.weight = w;
		} else {
			s.wi = material_refract(wo, n, cos_o, eta);
			s.weight = w * tint;
			s.transmitted = 1;
		}
		return s;
	}
	if (u.x < c0)
		s.wi = material_ggx_sample(n, wo, m->coat.y, u.y, u.z);
	else if (u.x < c1)
		s.wi = material_ggx_sample(n, wo, m->reflect.w, u.y, u.z);
	else
		s.wi = material_sample_cosine(n, u.y, u.z);
	float3 f = material_eval(m, l, n, wo, s.wi, &s.pdf);
	if (s.pdf > 0.0f)
		s.weight = f / s.pdf;
	return s;
}
