/* lower_texture.c: a scene material into the kernels' dev_material, and its
 * pigment's tree of patterns into the patterns, warps and maps buffers.
 *
 * Each use of a pattern pigment is flattened with the transformations it is
 * placed under, so a pattern's rows map world space (a mesh's own space for a
 * mesh's textures) straight into its own space: the kernel applies one affine
 * map per pattern, however deep the pigment sits in maps.
 *
 * A pattern of whole textures and a layered texture become several
 * dev_materials: the one the primitives use, and the entries' and lower
 * layers' materials, kept in lt->subs (placed the same way) and appended after
 * every other material at the end (lower_textures_append). Each holds the
 * object's interior. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"

/* How deep pigments nest in maps on the device (texture.cl's stack holds the
 * pigments waiting at one depth and one at each above). */
#define NEST_MAX 6
/* How deep patterns of whole textures nest: texture.cl blends at most
 * 2^TEXTURE_NEST_MAX textures at a point (TEXTURE_BLEND). */
#define TEXTURE_NEST_MAX 3

static void *grow_to(void *p, int *cap, int need, size_t size)
{
	if (need <= *cap)
		return p;
	int cap2 = *cap ? *cap : 16;
	while (cap2 < need)
		cap2 *= 2;
	p = realloc(p, (size_t)cap2 * size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	*cap = cap2;
	return p;
}

static float4 row(const xform *t, int i)
{
	return (float4){ (float)t->m[i][0], (float)t->m[i][1], (float)t->m[i][2], (float)t->m[i][3] };
}

static float4 f4v(const double v[4])
{
	return (float4){ (float)v[0], (float)v[1], (float)v[2], (float)v[3] };
}

static dev_map_entry entry_colour(const float c[5], double value)
{
	return (dev_map_entry){ .colour = { c[0], c[1], c[2], c[3] }, .transmit = c[4], .value = (float)value,
	                        .pigment = -1, .material = -1 };
}

static xform inverse_or_identity(const xform *t, src_loc loc)
{
	xform inv;
	if (lower_invert(t, &inv) == 0)
		return inv;
	diag_warning(loc, "a pattern with a singular transformation (a scale of 0?) is left untransformed");
	return scene_xform_identity();
}

static float decode(const scene_image *im, float c)
{
	switch (im->decode) {
	case SCENE_DECODE_SRGB: return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
	case SCENE_DECODE_POWER: return c > 0 ? powf(c, im->gamma) : c;
	default: return c;
	}
}

/* The scene's images into the texels buffer, in the working gamma: each file's
 * values decoded by its gamma (POV-Ray 3.7's rules, eval_pattern.c) and
 * encoded by film_gamma; with gamma correction off (film_gamma 0) the values
 * stay as they are unless the image_map gave a gamma, which decodes them. */
static void lower_images(lower_textures *lt, const scene *s)
{
	if (lt->images || s->n_images == 0)
		return;
	long total = 0;
	for (int i = 0; i < s->n_images; i++)   /* a plane of filters after the colours, for some */
		total += (long)s->images[i].width * s->images[i].height * (s->images[i].filter ? 2 : 1);
	if (total <= 0)
		return;
	lt->images = calloc(s->n_images, sizeof *lt->images);
	lt->texels = malloc((size_t)total * sizeof *lt->texels);
	if (!lt->images || !lt->texels) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	float g = s->film_gamma;
	for (int i = 0; i < s->n_images; i++) {
		const scene_image *im = &s->images[i];
		long n = (long)im->width * im->height;
		lt->images[i] = (dev_image){ .width = im->width, .height = im->height, .first = (int)lt->n_texels,
		                             .flags = (im->premultiplied ? IMAGE_PREMULTIPLIED : 0) |
		                                      (im->filter ? IMAGE_FILTER : 0) };
		bool transcode = im->decode != SCENE_DECODE_NONE && (g > 0 || im->gamma_given);
		for (long k = 0; k < n; k++) {
			const float *c = &im->rgba[4 * k];
			float a = c[3], rgb[3] = { c[0], c[1], c[2] };
			for (int j = 0; j < 3 && transcode; j++) {
				float v = im->premultiplied && a > 0 ? rgb[j] / a : rgb[j];
				v = decode(im, v);
				if (g > 0 && g != 1 && !im->data)
					v = v > 0 ? powf(v, 1 / g) : v;
				rgb[j] = im->premultiplied && a > 0 ? v * a : v;
			}
			lt->texels[lt->n_texels + k] = (float4){ rgb[0], rgb[1], rgb[2], a };
		}
		lt->n_texels += n;
		for (long k = 0; im->filter && k < n; k++)
			lt->texels[lt->n_texels + k] = (float4){ im->filter[k], 0, 0, 0 };
		lt->n_texels += im->filter ? n : 0;
	}
	lt->n_images = s->n_images;
}

/* What the materials of one surface share while they are lowered: the
 * object's interior, and whether they are a mesh's own. */
struct surface {
	const scene_material *interior;
	int local;
	bool uv;   /* the object's uv_mapping: every texture of it is uv_mapped */
};

static int lower_layers(lower_textures *lt, const scene *s, const struct surface *sf, int t, const xform *outer,
                        int below, int depth);

/* The pigment s->pigments[node] placed by to_world (the transformations
 * outside it, its space to world); returns its dev_pattern's index. The outer
 * transformations join the front of its warps' list as POV-Ray's do (dev_warp):
 * the front transformation becomes the rows, the others transform warps.
 * With sf, the pigment is a pattern of whole textures at texture depth depth:
 * its entries' textures become materials in lt->subs, placed by every
 * transformation of the pattern (POV-Ray evaluates them at the pattern's point). */
static int flatten(lower_textures *lt, const scene *s, int node, const xform *to_world, int depth,
                   const struct surface *sf, bool uv)
{
	const scene_pigment *pg = &s->pigments[node];
	xform identity = scene_xform_identity();
	if (pg->uv) {   /* POV-Ray ignores what is around a uv_mapped pigment */
		uv = true;
		to_world = &identity;
	}
	if (uv)
		lt->uses_uv = 1;
	const scene_warp *w = pg->warps;
	int n_warps = pg->n_warps;
	xform front = *to_world, inner = *to_world;   /* inner: every transformation, for nested pigments */
	if (n_warps > 0 && w[0].kind == WARP_TRANSFORM) {
		front = scene_xform_then(&w[0].xf, to_world);
		w++;
		n_warps--;
	}
	for (int i = pg->n_warps - 1; i >= 0; i--)   /* written last, applied first */
		if (pg->warps[i].kind == WARP_TRANSFORM)
			inner = scene_xform_then(&pg->warps[i].xf, &inner);
	/* A nested pigment sees this one's point after all its warps; where a warp
	 * is no matrix, that point is handed over on the device (PATTERN_IN_PARENT). */
	bool hand_over = false;
	for (int i = 0; i < n_warps; i++)
		hand_over |= w[i].kind != WARP_TRANSFORM;
	xform inv = inverse_or_identity(&front, pg->loc);
	int at = lt->n_patterns++;
	lt->patterns = grow_to(lt->patterns, &lt->cap_patterns, lt->n_patterns, sizeof *lt->patterns);
	dev_pattern d = {
		.rows = { row(&inv, 0), row(&inv, 1), row(&inv, 2) },
		.kind = pg->kind, .wave = pg->wave, .noise_generator = scene_noise_generator(s, pg),
		.flags = (pg->normal_map ? PATTERN_NORMAL_MAP : 0) | (pg->no_bump_scale ? PATTERN_NO_BUMP_SCALE : 0) |
		         (uv ? PATTERN_UV : 0),
		.frequency = (float)pg->frequency, .phase = (float)pg->phase, .wave_exponent = (float)pg->wave_exponent,
		.bump_size = (float)pg->bump_size, .normal = { (float)pg->accuracy, (float)pg->altitude[0], (float)pg->altitude[1], 0 },
		.params = { f4v(pg->params[0]), f4v(pg->params[1]) },
		.warp_first = lt->n_warps, .warp_count = n_warps,
		.map_first = lt->n_maps, .map_count = pg->n_map,
	};
	if (pg->kind == PATTERN_WAVES || pg->kind == PATTERN_RIPPLES)   /* a scene-wide setting in POV-Ray */
		d.params[0].x = (float)s->number_of_waves;
	lt->warps = grow_to(lt->warps, &lt->cap_warps, lt->n_warps + n_warps, sizeof *lt->warps);
	for (int i = 0; i < n_warps; i++) {
		dev_warp dw = { .a = f4v(w[i].a), .b = f4v(w[i].b), .c = f4v(w[i].c), .d = f4v(w[i].d), .kind = w[i].kind,
		                .classic = w[i].classic };
		if (w[i].kind == WARP_TRANSFORM) {
			xform t = inverse_or_identity(&w[i].xf, pg->loc);
			dw.a = row(&t, 0), dw.b = row(&t, 1), dw.c = row(&t, 2);
		}
		lt->warps[lt->n_warps++] = dw;
	}
	/* the map's entries side by side; nested pigments go after them */
	int first = lt->n_maps;
	lt->n_maps += pg->n_map;
	lt->maps = grow_to(lt->maps, &lt->cap_maps, lt->n_maps, sizeof *lt->maps);
	struct surface sub = { 0 };   /* a uv_mapped pattern's textures are uv_mapped */
	if (sf) {
		sub = *sf;
		sub.uv |= uv;
	}
	for (int i = 0; i < pg->n_map; i++) {
		const scene_map_entry *e = &pg->map[i];
		dev_map_entry de = entry_colour(e->colour, e->value);
		if (sf)
			de.material = lower_layers(lt, s, &sub, e->texture, &inner, -1, depth + 1);
		else if (e->pigment >= 0 && depth + 1 < NEST_MAX && hand_over) {
			de.pigment = flatten(lt, s, e->pigment, &identity, depth + 1, NULL, false);
			lt->patterns[de.pigment].flags |= PATTERN_IN_PARENT;
		} else if (e->pigment >= 0 && depth + 1 < NEST_MAX)
			de.pigment = flatten(lt, s, e->pigment, &inner, depth + 1, NULL, uv);
		else if (e->pigment >= 0)
			diag_warning(pg->loc, "pigments nested more than %d deep in maps: the deeper ones are "
			             "their average colour", NEST_MAX);
		lt->maps[first + i] = de;
		if (!sf && (e->colour[3] != 0 || e->colour[4] != 0))
			lt->see_through = 1;
	}
	if (pg->kind == PATTERN_IMAGE_PATTERN || pg->kind == PATTERN_BUMP_MAP || pg->kind == PATTERN_MATERIAL_MAP ||
	    pg->kind == PATTERN_DENSITY_FILE)
		lower_images(lt, s);
	if (pg->kind == PATTERN_IMAGE_MAP) {
		/* its one map entry is its average; texture_image reads the image */
		lower_images(lt, s);
		const scene_image *im = &s->images[(int)pg->params[0][0]];
		if (pg->params[0][3] != 0 || pg->params[1][0] != 0 || pg->params[1][1] != 0 || im->average[3] < 1)
			lt->see_through = 1;   /* once's outside, filter all, transmit all, alpha */
	}
	lt->patterns[at] = d;
	return at;
}

/* Whether m's patterns are uv_mapped, by itself or by its object; a
 * texture { uv_mapping } is placed by its own transformations only. */
static bool material_uv(const struct surface *sf, const scene_material *m, const xform **to_world)
{
	if (m->uv != SCENE_UV_NONE)
		*to_world = &m->uv_xf;
	return m->uv != SCENE_UV_NONE || sf->uv;
}

/* One texture's material (no layers, no pattern of textures), placed by
 * to_world, with the surface's interior. */
static dev_material lower_plain(lower_textures *lt, const scene *s, const struct surface *sf, const scene_material *m,
                                const xform *to_world)
{
	const float *p = m->pigment;
	const float *al = s->ambient_light;
	const scene_material *in = sf->interior;
	int local = sf->local;
	dev_material d = {
		.pigment = { p[0], p[1], p[2], p[3] },
		.ambient = { m->ambient[0] * al[0], m->ambient[1] * al[1], m->ambient[2] * al[2], p[4] },
		.emission = { m->emission[0], m->emission[1], m->emission[2], m->diffuse },
		.highlight = { m->phong, m->phong_size, m->specular, m->roughness > 0 ? 1 / m->roughness : 0 },
		.reflection = { m->reflection[0], m->reflection[1], m->reflection[2], m->reflection_falloff },
		/* POV-Ray raises the reflected colour to 1 / exponent */
		.reflection_max = { m->reflection_max[0], m->reflection_max[1], m->reflection_max[2],
		                    m->reflection_exponent != 0 ? 1 / m->reflection_exponent : 1 },
		.terms = { m->brilliance, m->metallic, m->reflection_metallic, m->reflection_fresnel },
		.interior = { in->ior > 0 ? in->ior : 1, in->fade_distance, in->fade_power, m->conserve_energy },
		.fade_color = { in->fade_color[0], in->fade_color[1], in->fade_color[2], 0 },
		.pattern = -1,
		.normal = -1,
		.below = -1,
		.flags = (local ? MATERIAL_LOCAL : 0) | (m->roughness_set ? MATERIAL_ROUGH : 0),
		.noise_generator = s->noise_generator,
		.irid = { m->irid, m->irid_thickness, m->irid_turbulence, m->crand },
		.irid_wavelength = { s->irid_wavelength[0], s->irid_wavelength[1], s->irid_wavelength[2],
		                     in->caustics * 45 },
	};
	if (p[3] != 0 || p[4] != 0)
		lt->see_through = 1;
	d.media = lower_media(lt, s, in->media, to_world, &d.n_media);
	bool uv = material_uv(sf, m, &to_world);
	if (m->pattern >= 0 && m->pattern < s->n_pigments)
		d.pattern = flatten(lt, s, m->pattern, to_world, 0, NULL, uv);
	/* the kernels do not perturb the normals of a mesh's own textures yet */
	if (m->normal >= 0 && m->normal < s->n_pigments && !local)
		d.normal = flatten(lt, s, m->normal, to_world, 0, NULL, uv);
	return d;
}

static int add_sub(lower_textures *lt)
{
	lt->subs = grow_to(lt->subs, &lt->cap_subs, lt->n_subs + 1, sizeof *lt->subs);
	return lt->n_subs++;
}

int lower_texture_pigment(lower_textures *lt, const scene *s, int pigment)
{
	xform identity = scene_xform_identity();
	return flatten(lt, s, pigment, &identity, 0, NULL, false);
}

int lower_texture_density(lower_textures *lt, const scene *s, int pattern, const float rgb[3], const xform *to_world)
{
	scene_material m = scene_default_material();
	for (int k = 0; k < 3; k++)
		m.pigment[k] = rgb[k];
	m.pattern = pattern;
	struct surface sf = { &m, 0, false };
	dev_material d = lower_plain(lt, s, &sf, &m, to_world);
	int at = add_sub(lt);
	lt->subs[at] = d;
	return at;
}

/* A texture's material placed by to_world (its own transformations in it) at
 * texture depth depth: a pattern of whole textures, whose entries go into
 * lt->subs; deeper than TEXTURE_NEST_MAX, its average texture, warned about. */
static dev_material lower_one(lower_textures *lt, const scene *s, const struct surface *sf, const scene_material *m,
                              const xform *to_world, int depth)
{
	dev_material d = lower_plain(lt, s, sf, m, to_world);
	if (m->texture_map < 0 || m->texture_map >= s->n_pigments)
		return d;
	if (depth >= TEXTURE_NEST_MAX) {
		diag_warning(s->pigments[m->texture_map].loc, "patterns of whole textures nested more than %d deep: "
		             "the deeper ones are their average texture", TEXTURE_NEST_MAX);
		return d;
	}
	d.flags |= MATERIAL_TEXTURE_MAP;
	bool uv = material_uv(sf, m, &to_world);
	d.pattern = flatten(lt, s, m->texture_map, to_world, depth, sf, uv);
	return d;
}

/* The layers of texture t of the pool, placed in outer (the space of the
 * texture that holds them), into lt->subs; the bottom one's below is below.
 * Returns the top layer's index in lt->subs, or below when t is none. A
 * layered texture in the pool (t's layers) is its layers, in its own space. */
static int lower_layers(lower_textures *lt, const scene *s, const struct surface *sf, int t, const xform *outer,
                        int below, int depth)
{
	if (t < 0 || t >= s->n_textures)
		return below;
	const scene_material *m = &s->textures[t];
	int rest = lower_layers(lt, s, sf, m->below, outer, below, depth);
	xform own = scene_xform_then(&m->tex_xf, outer);
	if (m->layers >= 0)
		return lower_layers(lt, s, sf, m->layers, &own, rest, depth);
	int at = add_sub(lt);
	dev_material d = lower_one(lt, s, sf, m, &own, depth);
	d.below = rest;
	lt->subs[at] = d;
	return at;
}

dev_material lower_texture(lower_textures *lt, const scene *s, const scene_material *m, int local)
{
	struct surface sf = { m, local, m->uv == SCENE_UV_OBJECT };
	if (m->layers < 0)
		return lower_one(lt, s, &sf, m, &m->tex_xf, 0);
	int top = lower_layers(lt, s, &sf, m->layers, &m->tex_xf, -1, 0);
	return lt->subs[top];   /* a copy: the primitives' own index */
}

dev_material lower_interior_texture(lower_textures *lt, const scene *s, const scene_material *m)
{
	struct surface sf = { m, 0, m->uv == SCENE_UV_OBJECT };   /* the object's interior, as its outer side's */
	const scene_material *t = &s->textures[m->interior_texture - 1];
	xform to_world = scene_xform_then(&t->tex_xf, &m->interior_xf);
	if (t->layers < 0)
		return lower_one(lt, s, &sf, t, &to_world, 0);
	int top = lower_layers(lt, s, &sf, t->layers, &to_world, -1, 0);
	return lt->subs[top];
}

/* The same plain solid texture twice (two components with one declared
 * colour): one material, so that their weights add up on the device. */
static bool same_plain(const dev_material *a, const dev_material *b)
{
	return a->pattern < 0 && a->normal < 0 && a->below < 0 && !(a->flags & MATERIAL_TEXTURE_MAP) &&
	       memcmp(a, b, sizeof *a) == 0;
}

dev_material lower_texture_blob(lower_textures *lt, const scene *s, const scene_object *o, const dev_material *own)
{
	const scene_blob *bl = &s->blobs[o->poly];
	/* the blob's texture, for its components without one; POV-Ray's blob of
	 * several textures has no interior_texture */
	int own_sub = add_sub(lt);
	lt->subs[own_sub] = *own;
	lt->subs[own_sub].flags &= ~MATERIAL_INTERIOR;
	/* a pattern of no value whose map's entries are the components' textures,
	 * then the blob's own (what a point that no component reaches shows) */
	int at = lt->n_patterns++, first = lt->n_maps;
	lt->patterns = grow_to(lt->patterns, &lt->cap_patterns, lt->n_patterns, sizeof *lt->patterns);
	lt->patterns[at] = (dev_pattern){ .kind = PATTERN_SOLID, .map_first = first, .map_count = bl->n_parts + 1,
	                                  .rows = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
	lt->n_maps += bl->n_parts + 1;
	lt->maps = grow_to(lt->maps, &lt->cap_maps, lt->n_maps, sizeof *lt->maps);
	struct surface sf = { &o->material, 0, o->material.uv == SCENE_UV_OBJECT };
	for (int j = 0; j <= bl->n_parts; j++) {
		int t = j < bl->n_parts ? bl->part[j].texture - 1 : -1, m = own_sub;
		if (t >= 0) {   /* placed in the blob's space, which o->xf takes to world */
			int n_subs = lt->n_subs;
			m = lower_layers(lt, s, &sf, t, &o->xf, -1, 0);
			for (int k = 0; k < j && lt->n_subs == n_subs + 1; k++)
				if (lt->maps[first + k].material != own_sub &&
				    same_plain(&lt->subs[m], &lt->subs[lt->maps[first + k].material])) {
					lt->n_subs--;
					m = lt->maps[first + k].material;
					break;
				}
		}
		const dev_material *sm = &lt->subs[m];   /* its average colour, as a texture_map's entries have */
		lt->maps[first + j] = (dev_map_entry){ .colour = sm->pigment, .transmit = sm->ambient.w, .value = (float)j,
		                                       .pigment = -1, .material = m };
	}
	dev_material d = *own;
	d.flags = (d.flags & ~MATERIAL_INTERIOR) | MATERIAL_TEXTURE_MAP | MATERIAL_BLOB;
	d.pattern = at;
	d.normal = -1;
	d.below = -1;
	return d;
}

void lower_textures_append(lower_textures *lt, dev_material **mats, int *n_mats)
{
	int base = *n_mats;
	if (lt->n_subs == 0)
		return;
	*mats = realloc(*mats, (size_t)(base + lt->n_subs) * sizeof **mats);
	if (!*mats) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	memcpy(*mats + base, lt->subs, (size_t)lt->n_subs * sizeof *lt->subs);
	*n_mats = base + lt->n_subs;
	for (int i = 0; i < *n_mats; i++)
		if ((*mats)[i].below >= 0)
			(*mats)[i].below += base;
	for (int i = 0; i < lt->n_maps; i++)
		if (lt->maps[i].material >= 0)
			lt->maps[i].material += base;
	for (int i = 0; i < lt->n_media; i++)
		for (int k = 0; k < MEDIA_DENSITIES; k++)
			if (lt->media[i].density[k] >= 0)
				lt->media[i].density[k] += base;
	free(lt->subs);
	lt->subs = NULL;
	lt->n_subs = lt->cap_subs = 0;
}

void lower_textures_free(lower_textures *lt)
{
	free(lt->patterns);
	free(lt->subs);
	free(lt->warps);
	free(lt->maps);
	free(lt->images);
	free(lt->texels);
	free(lt->media);
	free(lt->media_at);
	memset(lt, 0, sizeof *lt);
}
