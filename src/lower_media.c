/* lower_media.c: the media of interiors and of the atmosphere as the kernels
 * read them (dev_media). An interior's media are a chain in scene.media, named
 * by its head; each chain becomes consecutive records once, however many
 * materials (a CSG's leaves, a texture's layers) hold it, so that the first
 * record names the interior for the rays inside it (kernels/media.cl). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lower.h"
#include "shape.h"

static void *grow_media(void *p, int *cap, size_t size)
{
	*cap = *cap ? 2 * *cap : 8;
	p = realloc(p, (size_t)*cap * size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return p;
}

/* The largest value a density's pigment takes in any channel: its map's
 * entries bound it (nested pigments in turn); an image, 1. Delta tracking
 * needs a bound it never passes. */
static float density_bound(const lower_textures *lt, int pattern, int depth)
{
	if (pattern < 0 || pattern >= lt->n_patterns || depth > 8)
		return 1;
	const dev_pattern *p = &lt->patterns[pattern];
	if (p->kind == PATTERN_IMAGE_MAP || p->map_count == 0)
		return 1;
	float b = 0;
	for (int i = p->map_first; i < p->map_first + p->map_count && i < lt->n_maps; i++) {
		const dev_map_entry *e = &lt->maps[i];
		float c = e->pigment >= 0 ? density_bound(lt, e->pigment, depth + 1)
		                          : fmaxf(e->colour.x, fmaxf(e->colour.y, e->colour.z));
		b = fmaxf(b, c);
	}
	return b;
}

/* The normal distribution's quantile p, from the chi-square one's for one
 * degree of freedom (the square of a normal variable): the z with P(|Z| > z)
 * = 2 min(p, 1 - p), below 0 for p below a half. */
static double normal_quantile(double p)
{
	double z = sqrt(lower_chdtri(1, 2 * fmin(p, 1 - p)));
	return p < 0.5 ? -z : z;
}

/* What methods 1 and 2's extra samples need (POV-Ray's Sample_Threshold: the
 * variance over the chi-square quantile at confidence for max_samples - 1
 * degrees of freedom, times that for the samples so far). */
static void extra_samples(const scene_media *m, dev_media *d)
{
	if (m->max_samples <= 1)
		return;
	double q = lower_chdtri(m->max_samples - 1, m->confidence);
	d->sampling.w = (float)(q > 0 ? m->variance / q : m->variance * 1e-10);
	d->chi_1 = (float)lower_chdtri(1, m->confidence);
	d->chi_z = (float)normal_quantile(1 - m->confidence);
}

static dev_media lower_one_media(lower_textures *lt, const scene *s, const scene_media *m, const xform *to_world)
{
	dev_media d = {
		.absorption = { (float)m->absorption[0], (float)m->absorption[1], (float)m->absorption[2],
		                (float)m->eccentricity },
		.emission = { (float)m->emission[0], (float)m->emission[1], (float)m->emission[2], 1 },
		.scattering = { (float)m->scattering[0], (float)m->scattering[1], (float)m->scattering[2],
		                (float)m->extinction },
		.density_rgb = { 1, 1, 1, 1 },
		.sampling = { (float)m->jitter, (float)m->aa_threshold, (float)m->ratio, 0 },
		.method = m->method,
		.intervals = m->intervals,
		.min_samples = m->min_samples,
		.max_samples = m->max_samples,
		.aa_level = m->aa_level,
		.type = m->type >= MEDIA_ISOTROPIC && m->type <= MEDIA_HG ? m->type : MEDIA_ISOTROPIC,
		.density = { -1, -1, -1, -1 },
	};
	extra_samples(m, &d);
	xform place = scene_xform_then(&m->xf, to_world);
	int n = 0;
	for (int k = 0; k < m->n_density && k < MEDIA_DENSITIES; k++) {
		if (m->density[k] < 0) {   /* a constant density only scales */
			d.density_rgb.x *= m->density_rgb[k][0];
			d.density_rgb.y *= m->density_rgb[k][1];
			d.density_rgb.z *= m->density_rgb[k][2];
			continue;
		}
		d.density[n] = lower_texture_density(lt, s, m->density[k], m->density_rgb[k], &place);
		d.emission.w *= density_bound(lt, lt->subs[d.density[n]].pattern, 0);
		n++;
	}
	d.emission.w *= fmaxf(d.density_rgb.x, fmaxf(d.density_rgb.y, d.density_rgb.z));
	return d;
}

int lower_media(lower_textures *lt, const scene *s, int head, const xform *to_world, int *n)
{
	*n = 0;
	if (head <= 0 || head > s->n_media)
		return -1;
	if (!lt->media_at) {
		lt->media_at = malloc((size_t)s->n_media * sizeof *lt->media_at);
		if (!lt->media_at) {
			fprintf(stderr, "eclat: out of memory\n");
			diag_exit(1);
		}
		for (int i = 0; i < s->n_media; i++)
			lt->media_at[i] = -1;
	}
	int count = 0;
	for (int i = head - 1; i >= 0; i = s->media[i].prev)
		count++;
	*n = count;
	if (lt->media_at[head - 1] >= 0)
		return lt->media_at[head - 1];
	int first = lt->n_media;
	while (lt->n_media + count > lt->cap_media)
		lt->media = grow_media(lt->media, &lt->cap_media, sizeof *lt->media);
	lt->n_media += count;
	/* the chain runs from the last written: records keep the order written */
	int k = count;
	for (int i = head - 1; i >= 0; i = s->media[i].prev)
		lt->media[first + --k] = lower_one_media(lt, s, &s->media[i], to_world);
	lt->media_at[head - 1] = first;
	return first;
}

/* Whether o has an inside: a mesh only with its inside_vector. */
static bool has_inside(const scene *s, const scene_object *o)
{
	double d[3];
	if (!shape_of(o)->inside)
		return false;
	return o->shape != SHAPE_MESH || shape_mesh_inside_dir(s, o, d) == 0;
}

void lower_media_warn_open(const scene *s)
{
	for (int i = 0; i < s->n_objects; i++) {
		const scene_object *o = &s->objects[i];
		if (o->material.media && !has_inside(s, o) && !o->csg)
			diag_warning(o->loc, "media in a %s, which has no inside: as in POV-Ray, a ray that passes "
			             "through it carries them to the next surface it meets", shape_of(o)->name);
	}
}
