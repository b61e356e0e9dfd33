/* eval_material.c: pigment, finish, texture, normal, interior, material and the
 * maps. A pigment's pattern becomes a scene_pigment (eval_pattern.c) that the
 * kernels evaluate at each point; its average colour stays in pigment[] for
 * what needs one colour. A pattern of whole textures (texture_map, checker
 * texture { } texture { }) is a scene_pigment whose entries are textures of
 * the pool scene.textures; layered textures are a chain of textures there.
 * Patterns eclat does not have yet become their average, with one warning per
 * place (see eclat-scene(5), TEXTURES). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

/* ---- copying parts of a texture ---- */

static void copy_pigment(scene_material *d, const scene_material *s)
{
	memcpy(d->pigment, s->pigment, sizeof d->pigment);
	d->pattern = s->pattern;
	d->tex_xf = s->tex_xf;
}

static void copy_finish(scene_material *d, const scene_material *s)
{
	memcpy(d->ambient, s->ambient, sizeof d->ambient);
	d->diffuse = s->diffuse;
	d->brilliance = s->brilliance;
	memcpy(d->emission, s->emission, sizeof d->emission);
	d->phong = s->phong;
	d->phong_size = s->phong_size;
	d->specular = s->specular;
	d->roughness = s->roughness;
	memcpy(d->reflection, s->reflection, sizeof d->reflection);
	memcpy(d->reflection_max, s->reflection_max, sizeof d->reflection_max);
	d->reflection_falloff = s->reflection_falloff;
	d->reflection_exponent = s->reflection_exponent;
	d->metallic = s->metallic;
	d->reflection_metallic = s->reflection_metallic;
	d->reflection_fresnel = s->reflection_fresnel;
	d->roughness_set = s->roughness_set;
	d->conserve_energy = s->conserve_energy;
	d->crand = s->crand;
	d->irid = s->irid;
	d->irid_thickness = s->irid_thickness;
	d->irid_turbulence = s->irid_turbulence;
}

static void copy_interior(scene_material *d, const scene_material *s)
{
	d->ior = s->ior;
	d->dispersion = s->dispersion;
	d->fade_distance = s->fade_distance;
	d->fade_power = s->fade_power;
	memcpy(d->fade_color, s->fade_color, sizeof d->fade_color);
	d->media = s->media;
	d->caustics = s->caustics;
}

void eval_apply_value(const value *v, scene_material *m)
{
	switch (v->kind) {
	case V_PIGMENT: copy_pigment(m, &v->mat); break;
	case V_FINISH: copy_finish(m, &v->mat); break;
	case V_TEXTURE:
		copy_pigment(m, &v->mat);
		copy_finish(m, &v->mat);
		m->normal = v->mat.normal;
		m->normal_amount = v->mat.normal_amount;
		m->texture_map = v->mat.texture_map;
		m->layers = v->mat.layers;
		m->uv = v->mat.uv;
		m->uv_xf = v->mat.uv_xf;
		break;
	case V_NORMAL:
		m->normal = v->mat.normal;
		m->normal_amount = v->mat.normal_amount;
		break;
	case V_INTERIOR: copy_interior(m, &v->mat); break;
	case V_MATERIAL: *m = v->mat; break;
	default: break;
	}
}

/* A texture on an object that has one is a layer on top of it in POV-Ray:
 * the object's texture becomes a layered one whose layers (the texture it had,
 * and tex on it) are in the pool scene.textures, each with its own space; the
 * layered texture's tex_xf starts as the identity and takes the
 * transformations written after it, for all its layers. An opaque solid top
 * layer hides the ones below: it replaces them. As POV-Ray, a pattern of whole
 * textures is neither layered over nor layered on another texture. For what
 * needs one colour, the layered texture's pigment mixes the layers' averages by
 * the top one's transparency, with the finish of the layer that shows most. */
void eval_apply_texture(struct eval *e, src_loc loc, scene_material *m, bool textured, const scene_material *tex)
{
	bool opaque = tex->pattern < 0 && tex->texture_map < 0 && tex->layers < 0 && tex->pigment[3] == 0 &&
	              tex->pigment[4] == 0;
	if (!textured || opaque) {
		eval_apply_value(&(value){ .kind = V_TEXTURE, .mat = *tex }, m);
		return;
	}
	if (m->texture_map >= 0 || tex->texture_map >= 0) {
		eval_error(e, loc, m->texture_map >= 0 ? "cannot layer a texture over a pattern of whole textures"
		                                       : "cannot layer a pattern of whole textures over another texture");
		return;
	}
	scene_material below = *m, top = *tex;
	below.below = -1;
	top.below = scene_add_texture(e->s, &below);
	m->layers = scene_add_texture(e->s, &top);
	m->pattern = m->normal = -1;
	m->tex_xf = scene_xform_identity();
	double t = tex->pigment[3] + tex->pigment[4];
	if (t > 1)
		t = 1;
	for (int i = 0; i < 3; i++)
		m->pigment[i] = (float)(tex->pigment[i] * (1 - t) + m->pigment[i] * t);
	for (int i = 3; i < 5; i++)
		m->pigment[i] = (float)(m->pigment[i] * t);
	if (t < 0.5)
		copy_finish(m, tex);
}

/* ---- colour maps ---- */

struct map_point {
	double at, c[5];
	int pigment;             /* a pattern pigment, or -1 */
	int texture;             /* a texture_map's: the entry's texture in scene.textures */
};

/* The average over 0 to 1 of the colour a map gives: constant before its first
 * entry and after its last, linear between entries. */
static void map_average(const struct map_point *p, int n, double out[5])
{
	for (int k = 0; k < 5; k++)
		out[k] = 0;
	if (n == 0)
		return;
	double lo = p[0].at < 0 ? 0 : p[0].at > 1 ? 1 : p[0].at;
	double hi = p[n - 1].at < 0 ? 0 : p[n - 1].at > 1 ? 1 : p[n - 1].at;
	for (int k = 0; k < 5; k++)
		out[k] = p[0].c[k] * lo + p[n - 1].c[k] * (1 - hi);
	for (int i = 0; i + 1 < n; i++) {
		double a = p[i].at, b = p[i + 1].at;
		double ca = a < 0 ? 0 : a > 1 ? 1 : a, cb = b < 0 ? 0 : b > 1 ? 1 : b;
		if (cb <= ca)
			continue;
		for (int k = 0; k < 5; k++) {
			double fa = b > a ? p[i].c[k] + (p[i + 1].c[k] - p[i].c[k]) * (ca - a) / (b - a) : p[i].c[k];
			double fb = b > a ? p[i].c[k] + (p[i + 1].c[k] - p[i].c[k]) * (cb - a) / (b - a) : p[i].c[k];
			out[k] += (fa + fb) / 2 * (cb - ca);
		}
	}
}

struct map_build {
	struct map_point *p;
	int n;
	bool unordered;          /* entries without values (average): a plain mean */
	bool finish_set;
	scene_material first;   /* a texture_map's first texture, for its finish */
};

static void map_add(struct map_build *mb, double at, const double c[5], int pigment, int texture)
{
	mb->p = eval_xrealloc(mb->p, (mb->n + 1) * sizeof *mb->p);
	mb->p[mb->n].at = at;
	mb->p[mb->n].pigment = pigment;
	mb->p[mb->n].texture = texture;
	memcpy(mb->p[mb->n].c, c, sizeof mb->p[mb->n].c);
	mb->n++;
}

/* The colour an entry's value gives: a colour, a pigment, a texture (which
 * goes into the pool, *pigment its index there). */
static int entry_color(struct eval *e, const ast_node *at, value *v, int map_kw, struct map_build *mb, double c[5],
                       int *pigment)
{
	*pigment = -1;
	if (map_kw == KW_COLOR_MAP || map_kw == KW_COLOUR_MAP) {
		if (!eval_is_numeric(v->kind)) {
			eval_error(e, at->loc, "expected a colour in a colour_map entry, found %s", eval_kind_name(v->kind));
			return -1;
		}
		eval_widen(v, 5, c);
		return 0;
	}
	val_kind want = map_kw == KW_PIGMENT_MAP || map_kw == KW_DENSITY_MAP ? V_PIGMENT : V_TEXTURE;
	if (v->kind != want && !(want == V_PIGMENT && eval_is_numeric(v->kind))) {
		eval_error(e, at->loc, "expected %s in a %s entry, found %s", eval_kind_name(want),
		           ast_keyword_name(map_kw), eval_kind_name(v->kind));
		return -1;
	}
	if (eval_is_numeric(v->kind))
		eval_widen(v, 5, c);
	else
		for (int k = 0; k < 5; k++)
			c[k] = v->mat.pigment[k];
	if (want == V_PIGMENT && !eval_is_numeric(v->kind))
		*pigment = v->mat.pattern;
	if (want == V_TEXTURE && !mb->finish_set) {
		mb->first = v->mat;
		mb->finish_set = true;
	}
	if (want == V_TEXTURE)
		*pigment = scene_add_texture(e->s, &v->mat);
	return 0;
}

/* [Value PIGMENT_BODY] of a pigment_map (and of a density's density_map, whose
 * entries are densities), [Value TEXTURE_BODY] of a texture_map:
 * the items after the value are those of a pigment { } or texture { }. */
static int body_entry(struct eval *e, const ast_node *entry, int map_kw, struct map_build *mb)
{
	double at = 1, c[5];
	/* The maps of the average pattern may leave the value out (a weight of 1):
	 * the first item is the value when it is a float and more items follow. */
	int first = 0;
	if (entry->n_kids >= 2 && AST_IS_EXPRESSION(entry->kids[0]->kind)) {
		value v0;
		if (eval_expr(e, entry->kids[0], &v0))
			return -1;
		first = v0.kind == V_FLOAT;
		at = first ? v0.v[0] : 1;
		eval_value_free(&v0);
	}
	if (entry->n_kids < 1) {
		eval_error(e, entry->loc, "a map entry is [Value ITEMS]");
		return -1;
	}
	if (!first)
		mb->unordered = true;
	int body_kw = map_kw == KW_PIGMENT_MAP || map_kw == KW_DENSITY_MAP ? KW_PIGMENT : KW_TEXTURE;
	ast_node body = { .kind = AST_BLOCK, .kw = body_kw, .loc = entry->kids[first]->loc, .kids = entry->kids + first,
	                  .n_kids = entry->n_kids - first };
	value v;
	if (eval_material_value(e, &body, &v))
		return -1;
	int pigment;
	int rc = entry_color(e, entry->kids[first], &v, map_kw, mb, c, &pigment);
	bool tex = map_kw == KW_TEXTURE_MAP;
	if (rc == 0)
		map_add(mb, at, c, tex ? -1 : pigment, tex ? pigment : -1);
	eval_value_free(&v);
	return rc;
}

/* [0.5 red 1 green 0.5]: the grammar reads "0.5 red 1" as a colour of base 0.5.
 * POV-Ray reads the value, then a colour: undo the first, with black instead. */
static int split_entry(struct eval *e, const ast_node *n, value *at, value *col)
{
	if (n->kind == AST_COLOR && n->n_kids == 2 && ast_keyword_class(n->kw) == KWC_COMP) {
		value base;
		if (split_entry(e, n->kids[0], at, &base))
			return -1;
		return eval_component(e, n, &base, col);
	}
	*col = (value){ .kind = V_COLOR, .n = 5 };
	return eval_expr(e, n, at);
}

/* [Value ITEM [MODIFIERS]] or POV-Ray's old [Value1, Value2 COLOR1 COLOR2]: the
 * modifiers after a pigment or texture (scale, rotate...) shape its pattern,
 * which eclat averages anyway. */
static int map_entry(struct eval *e, const ast_node *entry, int map_kw, struct map_build *mb)
{
	value v[4] = { 0 };
	const ast_node *at[4];
	int n = 0, rc = 0;
	if (entry->n_kids == 1 && entry->kids[0]->kind == AST_COLOR && entry->kids[0]->n_kids == 2) {
		at[0] = at[1] = entry->kids[0];
		rc = split_entry(e, entry->kids[0], &v[0], &v[1]);
		n = rc == 0 ? 2 : 0;
	}
	for (int i = n ? entry->n_kids : 0; rc == 0 && i < entry->n_kids; i++) {
		const ast_node *k = entry->kids[i];
		xform t = scene_xform_identity();
		if (AST_IS_EXPRESSION(k->kind) || (k->kind == AST_BLOCK && n > 0 && !eval_transform_item(e, NULL, k, &t))) {
			if (n == 4) {
				rc = eval_not_valid(e, k, "a map entry");
				break;
			}
			at[n] = k;
			rc = AST_IS_EXPRESSION(k->kind) ? eval_expr(e, k, &v[n]) : eval_block_value(e, k, &v[n]);
			n++;
		} else if (n == 0 || (k->kind != AST_ARG && k->kind != AST_FLAG && k->kind != AST_BLOCK)) {
			rc = eval_not_valid(e, k, "a map entry");
		}
	}
	int half = n == 4 ? 2 : 1;
	if (rc == 0 && n != 2 && n != 4) {
		eval_error(e, entry->loc, "a map entry is [Value ITEM] or [Value1, Value2 ITEM1 ITEM2]");
		rc = -1;
	}
	for (int i = 0; rc == 0 && i < half; i++) {
		double c[5];
		int pigment;
		if (v[i].kind != V_FLOAT) {
			eval_error(e, at[i]->loc, "expected a float, found %s", eval_kind_name(v[i].kind));
			rc = -1;
		} else if ((rc = entry_color(e, at[half + i], &v[half + i], map_kw, mb, c, &pigment)) == 0) {
			map_add(mb, v[i].v[0], c, pigment, -1);
		}
	}
	for (int i = 0; i < n; i++)
		eval_value_free(&v[i]);
	return rc;
}

/* A map's entries, kept as a pigment of kind PATTERN_SOLID that patterns copy
 * their map from. */
static int map_pigment(struct eval *e, const struct map_build *mb, src_loc loc)
{
	scene_pigment pg;
	eval_pattern_defaults(&pg, PATTERN_SOLID, loc);
	pg.map = eval_xrealloc(NULL, mb->n * sizeof *pg.map);
	pg.n_map = mb->n;
	for (int i = 0; i < mb->n; i++) {
		pg.map[i] = (scene_map_entry){ .value = mb->p[i].at, .pigment = mb->p[i].pigment,
		                               .texture = mb->p[i].texture };
		for (int k = 0; k < 5; k++)
			pg.map[i].colour[k] = (float)mb->p[i].c[k];
	}
	return scene_add_pigment(e->s, &pg);
}

/* color_map { [MAP_IDENTIFIER] [Value COLOR]... }, pigment_map, texture_map: the
 * average colour (in a texture_map, with its first texture's finish). */
static int map_block(struct eval *e, const ast_node *b, value *out)
{
	struct map_build mb = { 0 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	*out = (value){ .kind = V_COLOR_MAP, .mat = e->default_mat };
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		value v;
		if (item->kind == AST_ENTRY && (b->kw == KW_PIGMENT_MAP || b->kw == KW_TEXTURE_MAP || b->kw == KW_DENSITY_MAP))
			rc = body_entry(e, item, b->kw, &mb);
		else if (item->kind == AST_ENTRY)
			rc = map_entry(e, item, b->kw, &mb);
		else if (AST_IS_EXPRESSION(item->kind) && mb.n == 0 && (rc = eval_expr(e, item, &v)) == 0) {
			if (v.kind != V_COLOR_MAP)
				rc = eval_not_valid(e, item, ast_keyword_name(b->kw));
			*out = v;
			free(mb.p);
			eval_cursor_free(&c);
			return rc;
		} else if (rc == 0)
			rc = eval_not_valid(e, item, ast_keyword_name(b->kw));
	}
	eval_cursor_free(&c);
	if (rc == 0 && !err) {
		double avg[5] = { 0 }, weights = 0;
		for (int i = 0; i < mb.n; i++)   /* the average pattern's: values are weights, 1 if left out */
			weights += mb.p[i].at;
		for (int i = 0; i < mb.n; i++)
			for (int k = 0; k < 5 && weights != 0; k++)
				out->v[k] += mb.p[i].c[k] * mb.p[i].at / weights;
		if (mb.unordered)
			memcpy(avg, out->v, sizeof avg);
		else
			map_average(mb.p, mb.n, avg);
		if (mb.finish_set)
			out->mat = mb.first;
		for (int k = 0; k < 5; k++)
			out->mat.pigment[k] = (float)avg[k];
		out->mat.pattern = mb.n == 0 ? -1 : map_pigment(e, &mb, b->loc);
		out->n = mb.unordered;   /* entries without values: only the average pattern takes them */
	}
	free(mb.p);
	return rc || err ? -1 : 0;
}

/* ---- patterns ---- */

static bool is_pattern(const ast_node *item)
{
	if (item->kind == AST_ARG)
		return item->kw == KW_GRADIENT || item->kw == KW_SPIRAL1 || item->kw == KW_SPIRAL2;
	if (item->kind != AST_FLAG)
		return false;
	switch (item->kw) {
	case KW_AGATE: case KW_BOXED: case KW_BOZO: case KW_BRICK: case KW_BUMPS: case KW_CELLS:
	case KW_CHECKER: case KW_CRACKLE: case KW_CYLINDRICAL: case KW_DENTS: case KW_FACETS:
	case KW_GRANITE: case KW_HEXAGON: case KW_LEOPARD: case KW_MARBLE: case KW_ONION: case KW_PLANAR:
	case KW_QUILTED: case KW_RADIAL: case KW_RIPPLES: case KW_SPHERICAL: case KW_SPOTTED: case KW_WAVES:
	case KW_WOOD: case KW_WRINKLES:
		return true;
	default:
		return false;
	}
}

/* Items that shape a pattern: nothing to eclat, which averages it. */
static bool is_pattern_modifier(struct eval *e, const ast_node *item)
{
	(void)e;
	if (item->kind == AST_ARG)
		switch (item->kw) {
		case KW_TURBULENCE: case KW_OCTAVES: case KW_OMEGA: case KW_LAMBDA: case KW_FREQUENCY:
		case KW_PHASE: case KW_AGATE_TURB: case KW_BRICK_SIZE: case KW_MORTAR:
		case KW_INTERIOR: case KW_EXPONENT:   /* interior 2, .5 and exponent 3 of fractal patterns */
			return true;
		default:
			return false;
		}
	if (item->kind == AST_FLAG)
		switch (item->kw) {
		case KW_RAMP_WAVE: case KW_TRIANGLE_WAVE: case KW_SINE_WAVE: case KW_SCALLOP_WAVE:
		case KW_CUBIC_WAVE: case KW_POLY_WAVE: case KW_UV_MAPPING:
			return true;
		default:
			return false;
		}
	return item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, "warp") == 0;
}

/* A pattern being read: the pigment it makes when eclat has the pattern
 * (kind > 0), and what its average is made of: its map, or the colours listed
 * after it. */
#define LIST_MAX 6
struct pattern {
	const ast_node *at;      /* the pattern keyword, or NULL: a solid colour */
	char name[40];
	int kind;                /* PATTERN_, or -1: one eclat does not have */
	scene_pigment pg;        /* its modifiers; its map comes at the end */
	bool inherited;          /* from a declared pigment: its average unless a map follows */
	double base[5];
	double list[LIST_MAX][5];
	int list_pigment[LIST_MAX];
	int list_texture[LIST_MAX];   /* a texture's list: the textures (scene.textures) */
	int n_list;
	bool has_map;
	double map[5];
	int map_pigment;         /* the map's entries (map_pigment), or -1 */
	scene_material map_mat;  /* a texture_map's finish */
	bool map_finish;         /* the map is a texture_map */
	bool uv;                 /* uv_mapping was written */
	const scene_pigment *continues;   /* the pigment it modifies, whose written map it keeps */
};

/* Whether item is uv_mapping; the scene learns that it has some. */
static bool is_uv_mapping(struct eval *e, const ast_node *item)
{
	bool uv = item->kind == AST_FLAG && item->kw == KW_UV_MAPPING;
	e->s->uv_mapped |= uv;
	return uv;
}

/* The patterns whose map POV-Ray's parser always makes, as a list (given or
 * its defaults). */
static bool list_pattern(int kind)
{
	switch (kind) {
	case PATTERN_CHECKER: case PATTERN_HEXAGON: case PATTERN_BRICK: case PATTERN_SQUARE:
	case PATTERN_TRIANGULAR: case PATTERN_CUBIC: case PATTERN_OBJECT:
		return true;
	default:
		return false;
	}
}

/* The map of the pigment being made: its map's, its list's, the map of the
 * pigment it modifies when that one was written, or POV-Ray's default. */
static void pattern_map(struct eval *e, struct pattern *p)
{
	scene_pigment *pg = &p->pg;
	if (pg->kind == PATTERN_IMAGE_MAP)
		return;   /* a colour of its own at each point: its map is its average */
	const scene_pigment *from = p->has_map && p->map_pigment >= 0 ? &e->s->pigments[p->map_pigment] : NULL;
	free(pg->map);
	pg->map = NULL;
	pg->n_map = 0;
	if (from) {
		pg->map = eval_xrealloc(NULL, from->n_map * sizeof *pg->map);
		memcpy(pg->map, from->map, from->n_map * sizeof *pg->map);
		pg->n_map = from->n_map;
	} else if (p->n_list) {
		pg->map = eval_xrealloc(NULL, p->n_list * sizeof *pg->map);
		for (int i = 0; i < p->n_list; i++) {
			pg->map[i] = (scene_map_entry){ .value = i, .pigment = p->list_pigment[i],
			                                .texture = p->list_texture[i] };
			for (int k = 0; k < 5; k++)
				pg->map[i].colour[k] = (float)p->list[i][k];
		}
		pg->n_map = p->n_list;
	} else if (p->continues && p->continues->map_written && !list_pattern(pg->kind)) {
		pg->map = eval_xrealloc(NULL, p->continues->n_map * sizeof *pg->map);
		memcpy(pg->map, p->continues->map, p->continues->n_map * sizeof *pg->map);
		pg->n_map = p->continues->n_map;
		return;
	} else {
		eval_pattern_default_map(pg);
		pg->map_written = list_pattern(pg->kind);
		return;
	}
	pg->map_written = true;
}

static void pattern_result(struct eval *e, struct pattern *p, double c[5], int *pigment)
{
	*pigment = -1;
	if (p->kind > 0) {
		eval_pavement_check(e, &p->pg, p->at->loc);   /* an error makes the evaluation fail */
		if (!(p->inherited && !p->has_map && !p->n_list))
			pattern_map(e, p);
		p->pg.uv |= p->uv;
		*pigment = scene_add_pigment(e->s, &p->pg);
		p->pg.map = NULL;
	}
	if (p->inherited && !p->has_map && !p->n_list) {
		memcpy(c, p->base, sizeof p->base);
		return;
	}
	if (p->kind > 0) {   /* its average, for what needs one colour */
		for (int k = 0; k < 5; k++) {
			double sum = 0;
			for (int i = 0; i < p->n_list; i++)
				sum += p->list[i][k];
			c[k] = p->has_map ? p->map[k] : p->n_list ? sum / p->n_list : k < 3 ? 0.5 : 0;
		}
		return;
	}
	const char *how = p->has_map ? "the average of its map" : p->n_list ? "the average of its colours"
	                : "rgb 0.5, the average of the default colour map";
	char key[64];
	snprintf(key, sizeof key, "pattern %s", p->name);
	if (strcmp(p->name, AST_WORD_AVERAGE) != 0 || !p->has_map)   /* average is its map's mean: exact */
		eval_warn_once(e, p->at->loc, key, "pattern '%s' is not supported yet; using %s", p->name, how);
	for (int k = 0; k < 5; k++) {
		double sum = 0;
		for (int i = 0; i < p->n_list; i++)
			sum += p->list[i][k];
		c[k] = p->has_map ? p->map[k] : p->n_list ? sum / p->n_list : k < 3 ? 0.5 : 0;
	}
}

static void start_pattern(struct pattern *p, const ast_node *item, const char *name)
{
	free(p->pg.map);
	*p = (struct pattern){ .at = item, .kind = eval_pattern_kind(name), .map_pigment = -1, .uv = p->uv };
	snprintf(p->name, sizeof p->name, "%s", name);
	eval_pattern_defaults(&p->pg, p->kind > 0 ? p->kind : PATTERN_SOLID, item->loc);
}

/* A map after an object pattern: POV-Ray's "Cannot use color_map with this
 * pattern type" (and its pigment_map, density_map, texture_map and normal_map
 * errors); the list in its block is all it takes. */
static int object_map(struct eval *e, const ast_node *item)
{
	eval_error(e, item->loc, "an object pattern takes no %s: write its two items (outside, inside) in its "
	           "block, after the object", ast_keyword_name(item->kw));
	return -1;
}

/* What an object pattern's list holds (object_pattern). */
enum object_list { OBJECT_LIST_PIGMENTS, OBJECT_LIST_TEXTURES, OBJECT_LIST_NORMALS };
static int object_pattern(struct eval *e, const ast_node *b, struct pattern *p, scene_material *m,
                          enum object_list what);

/* A pattern keyword with its argument (gradient x), or a pattern that is no
 * eclat keyword (cubic, square...): starts the pattern. 1 when item is none. */
static int pattern_start(struct eval *e, struct cursor *c, const ast_node *item, struct pattern *p)
{
	const ast_node *w = eval_slope_word(e, item);
	if (w) {   /* slope's arguments are no pattern modifiers: read them here */
		start_pattern(p, w, AST_WORD_SLOPE);
		int rc = eval_pattern_slope(e, c, item, &p->pg);
		if (rc == 2)
			p->kind = -1;
		return rc < 0 ? -1 : 0;
	}
	if (is_pattern(item)) {
		start_pattern(p, item, ast_keyword_name(item->kw));
		return p->kind > 0 ? eval_pattern_argument(e, item, &p->pg) : 0;
	}
	if (item->kind == AST_IDENT && !eval_lookup(e, item->str) && eval_pattern_kind(item->str) > 0) {
		int kind = eval_pattern_kind(item->str);
		if (kind == PATTERN_IMAGE_MAP || kind == PATTERN_IMAGE_PATTERN || kind == PATTERN_BUMP_MAP ||
		    kind == PATTERN_MATERIAL_MAP) {   /* without its file there is no image to read */
			eval_error(e, item->loc, "%s needs its block: %s { \"File\" ... }", item->str, item->str);
			return -1;
		}
		start_pattern(p, item, item->str);
		if (p->kind == PATTERN_TILING)
			return eval_pattern_tiling(e, c, item, &p->pg);
		return p->kind == PATTERN_DENSITY_FILE ? eval_density_file(e, c, item, &p->pg) : 0;
	}
	bool grey = item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, "pigment_pattern") == 0;
	if (item->kind == AST_FUNCTION || grey) {   /* function { }: the device runs it */
		start_pattern(p, item, scene_pattern_name(PATTERN_FUNCTION));
		int f, rc = grey ? eval_function_pigment_pattern(e, item, "the pattern is averaged", &f)
		                 : eval_function_pattern_index(e, item, "the pattern is averaged", &f);
		if (rc < 0)
			return -1;
		if (rc > 0) {   /* --skip-unsupported: averaged, as a pattern eclat lacks */
			p->kind = -1;
			return 0;
		}
		p->pg.params[0][0] = f;
		return 0;
	}
	return 1;
}

static int map_into(struct eval *e, const ast_node *item, struct pattern *p)
{
	value v;
	if (p->kind == PATTERN_OBJECT)
		return object_map(e, item);
	if (map_block(e, item, &v))
		return -1;
	p->has_map = true;
	p->map_pigment = v.mat.pattern;
	bool average = strcmp(p->name, AST_WORD_AVERAGE) == 0;
	if (v.n && !average)   /* POV-Ray's "Expected float": eclat kept the mean */
		p->map_pigment = -1;
	for (int k = 0; k < 5; k++)
		p->map[k] = average ? v.v[k] : v.mat.pigment[k];
	p->map_mat = v.mat;
	p->map_finish = item->kw == KW_TEXTURE_MAP;
	return 0;
}

static void list_add(struct pattern *p, const double c[5], int pigment, int texture)
{
	if (p->n_list < LIST_MAX) {
		p->list_pigment[p->n_list] = pigment;
		p->list_texture[p->n_list] = texture;
		memcpy(p->list[p->n_list++], c, sizeof p->list[0]);
	}
}

/* A POV-Ray pattern that is not an eclat keyword (mandel, average...) starts a
 * pattern; another POV-Ray word (quick_color, exterior...) is skipped; both
 * with the numbers after them. 1 when item is neither. */
static int pattern_word(struct eval *e, struct cursor *c, const ast_node *item, struct pattern *p)
{
	if (eval_slope_word(e, item))
		return pattern_start(e, c, item, p);
	const ast_node *w = eval_pov_word_item(e, item);
	if (!w)
		return 1;
	if (strcmp(eval_pov_word(w->str), "pattern") != 0)
		return eval_skip_pov_word(e, c, item);
	int err = 0;
	start_pattern(p, w, w->str);
	while (w == item && eval_next_optional(c, &err))
		;
	return err ? -1 : 0;
}

/* image_pattern { ... }, which starts the pattern; 1 when item is not one. */
static int image_pattern_block(struct eval *e, const ast_node *item, struct pattern *p)
{
	if (item->kind != AST_BLOCK || item->kw != KW_UNKNOWN || strcmp(item->str, AST_WORD_IMAGE_PATTERN) != 0)
		return 1;
	start_pattern(p, item, AST_WORD_IMAGE_PATTERN);
	return eval_image_pattern(e, item, &p->pg) ? -1 : 0;
}

/* A material_map's textures, as its map: entry i, the texture for material
 * number i. */
struct material_list {
	scene_map_entry *map;
	int n;
	scene_material first;
};

static int material_map_texture(struct eval *e, const ast_node *item, void *ctx)
{
	struct material_list *l = ctx;
	if (item->kind != AST_BLOCK || item->kw != KW_TEXTURE)
		return 1;
	value v;
	if (eval_material_value(e, item, &v))
		return -1;
	if (l->n == 0)
		l->first = v.mat;
	l->map = eval_xrealloc(l->map, (l->n + 1) * sizeof *l->map);
	l->map[l->n] = (scene_map_entry){ .value = l->n, .pigment = -1, .texture = scene_add_texture(e->s, &v.mat) };
	for (int k = 0; k < 5; k++)
		l->map[l->n].colour[k] = v.mat.pigment[k];
	l->n++;
	eval_value_free(&v);
	return 0;
}

/* material_map { [FORMAT] "File" [map_type N] [interpolate N] [once]
 * TEXTURE... }: a pattern of whole textures whose value is the image's
 * material number; 1 when item is not one. */
static int material_map_block(struct eval *e, const ast_node *item, struct pattern *p)
{
	if (item->kind != AST_BLOCK || item->kw != KW_UNKNOWN || strcmp(item->str, AST_WORD_MATERIAL_MAP) != 0)
		return 1;
	start_pattern(p, item, AST_WORD_MATERIAL_MAP);
	struct material_list l = { 0 };
	if (eval_material_map(e, item, &p->pg, material_map_texture, &l)) {
		free(l.map);
		return -1;
	}
	if (l.n == 0) {
		eval_error(e, item->loc, "a material_map needs a texture");
		return -1;
	}
	scene_pigment holder = p->pg;   /* the map, as a texture_map's */
	holder.map = l.map;
	holder.n_map = l.n;
	p->map_pigment = scene_add_pigment(e->s, &holder);
	p->has_map = p->map_finish = true;
	p->map_mat = l.first;
	for (int k = 0; k < 5; k++) {
		double sum = 0;
		for (int i = 0; i < l.n; i++)
			sum += l.map[i].colour[k];
		p->map[k] = sum / l.n;
	}
	return 0;
}

/* bump_map outside a normal, material_map outside a texture: POV-Ray's
 * error (where is what item may stand in); 1 when item is neither. */
static int misplaced_image(struct eval *e, const ast_node *item, const char *where)
{
	if (item->kind != AST_BLOCK || item->kw != KW_UNKNOWN)
		return 1;
	bool bump = strcmp(item->str, AST_WORD_BUMP_MAP) == 0, mat = strcmp(item->str, AST_WORD_MATERIAL_MAP) == 0;
	if ((!bump || strcmp(where, "a normal") == 0) && (!mat || strcmp(where, "a texture") == 0))
		return 1;
	eval_error(e, item->loc, "%s is only allowed in %s, not in %s", item->str, bump ? "a normal" : "a texture",
	           where);
	return -1;
}

/* ---- pigment ---- */

/* An expression in a pigment: a colour or a declared pigment, or a colour of the
 * list after a pattern (checker Red, Blue). */
static int pigment_value(struct eval *e, const ast_node *item, struct pattern *p, scene_material *m)
{
	value v;
	if (eval_expr(e, item, &v))
		return -1;
	double c[5];
	bool inherits = false;
	if (eval_is_numeric(v.kind)) {
		eval_widen(&v, 5, c);
	} else if (v.kind == V_PIGMENT) {
		for (int k = 0; k < 5; k++)
			c[k] = v.mat.pigment[k];
		inherits = v.str && !p->at;
		if (inherits) {   /* a pattern pigment: a colour_map after it replaces its own */
			start_pattern(p, item, v.str);
			p->inherited = true;
			memcpy(p->base, c, sizeof c);
			if (v.mat.pattern >= 0 && p->kind > 0) {   /* its modifiers, its map unless one follows */
				free(p->pg.map);
				p->pg = e->s->pigments[v.mat.pattern];
				p->pg.map = eval_xrealloc(NULL, p->pg.n_map * sizeof *p->pg.map);
				memcpy(p->pg.map, e->s->pigments[v.mat.pattern].map, p->pg.n_map * sizeof *p->pg.map);
			}
		}
	} else {
		eval_error(e, item->loc, "expected a colour or a pigment, found %s", eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	int pigment = v.kind == V_PIGMENT ? v.mat.pattern : -1;
	eval_value_free(&v);
	if (p->at && !inherits)
		list_add(p, c, pigment, -1);
	else if (!p->at) {
		for (int k = 0; k < 5; k++)
			m->pigment[k] = (float)c[k];
		m->pattern = v.kind == V_PIGMENT ? pigment : -1;
	}
	return 0;
}

static int pigment_item(struct eval *e, struct cursor *c, const ast_node *item, struct pattern *p,
                        scene_material *m)
{
	if (is_uv_mapping(e, item)) {   /* POV-Ray's UV_MAP_PATTERN around the rest of the pigment */
		p->uv = true;
		return 0;
	}
	int rc = pattern_start(e, c, item, p);
	if (rc <= 0)
		return rc;
	if (p->kind > 0 && (rc = eval_pattern_modifier(e, c, item, &p->pg)) <= 0)
		return rc;
	if ((rc = pattern_word(e, c, item, p)) <= 0)
		return rc;
	if (AST_IS_EXPRESSION(item->kind))
		return pigment_value(e, item, p, m);
	if (item->kind == AST_BLOCK && (item->kw == KW_COLOR_MAP || item->kw == KW_COLOUR_MAP ||
	                                item->kw == KW_PIGMENT_MAP || item->kw == KW_DENSITY_MAP)) {
		if (!p->at)
			eval_warning(e, item->loc, "a %s without a pattern is ignored", ast_keyword_name(item->kw));
		if (p->kind == PATTERN_AVERAGE && item->kw != KW_PIGMENT_MAP) {
			eval_error(e, item->loc, "average takes a pigment_map, not a %s", ast_keyword_name(item->kw));
			return -1;
		}
		return p->at ? map_into(e, item, p) : 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_PIGMENT && p->at) {   /* checker pigment {...}, ... */
		value v;
		if (eval_material_value(e, item, &v))
			return -1;
		double c[5];
		for (int k = 0; k < 5; k++)
			c[k] = v.mat.pigment[k];
		eval_value_free(&v);   /* its pattern's name, when it has one */
		list_add(p, c, v.mat.pattern, -1);
		return 0;
	}
	xform t = scene_xform_identity();
	rc = eval_transform_item(e, NULL, item, &t);
	if (rc > 0 && p->kind > 0 && eval_pattern_transform(e, &p->pg, &t, item->loc))
		return -1;   /* a pigment's transformations move its pattern only */
	if (rc != 0 || is_pattern_modifier(e, item))
		return rc < 0 ? -1 : 0;
	if ((rc = image_pattern_block(e, item, p)) <= 0 || (rc = misplaced_image(e, item, "a pigment")) <= 0)
		return rc;
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_IMAGE_MAP) == 0) {
		start_pattern(p, item, AST_WORD_IMAGE_MAP);
		if (eval_image_map(e, item, &p->pg))
			return -1;
		p->has_map = true;   /* its average, for what needs one colour */
		for (int k = 0; k < 5; k++)
			p->map[k] = p->pg.map[0].colour[k];
		return 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_OBJECT)
		return object_pattern(e, item, p, m, OBJECT_LIST_PIGMENTS);
	if ((item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) ||
	    item->kind == AST_FUNCTION) {
		start_pattern(p, item, item->kind == AST_FUNCTION ? "function" : item->str);   /* image_map... */
		return 0;
	}
	if (item->kind == AST_FLAG && item->kw == KW_ONCE)
		return 0;
	return eval_not_valid(e, item, "a pigment");
}

/* pigment { [COLOR | PIGMENT_IDENTIFIER] [PATTERN [COLORS] [MAP]] [MODIFIERS...] }
 * pattern: the name of its pattern, when it has one (NULL if not wanted). */
static int pigment_block(struct eval *e, const ast_node *b, scene_material *m, char **pattern)
{
	struct pattern p = { 0 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = pigment_item(e, &c, item, &p, m);
	eval_cursor_free(&c);
	if (rc || err) {
		free(p.pg.map);   /* an inherited pattern's copy of its map */
		return -1;
	}
	if (p.at && p.kind == PATTERN_AVERAGE && !p.has_map && !p.inherited) {   /* a declared one has its map */
		eval_error(e, p.at->loc, "average needs a pigment_map");
		free(p.pg.map);
		return -1;
	}
	if (p.at) {
		/* POV-Ray's texture keeps one pigment that a pigment { } modifies:
		 * a new pattern continues the old one's warps and the texture's
		 * transformations since (a declared pigment replaces them). tex_xf
		 * still moves the normal, so the pattern also gets its inverse in
		 * front, as a normal written after them does. */
		xform id = scene_xform_identity();
		bool moved = m->uv == SCENE_UV_NONE && !p.pg.uv && !p.uv && memcmp(&m->tex_xf, &id, sizeof id) != 0;
		const scene_pigment *old = m->pattern >= 0 && m->pattern < e->s->n_pigments ? &e->s->pigments[m->pattern]
		                                                                              : NULL;
		if (p.kind > 0 && !p.inherited && (moved || old) &&
		    eval_pattern_continue(e, &p.pg, old, moved ? &m->tex_xf : &id, p.at->loc)) {
			free(p.pg.map);
			return -1;
		}
		double col[5];
		p.continues = old;
		pattern_result(e, &p, col, &m->pattern);
		xform back = eval_xform_inverse(&m->tex_xf);
		if (moved && m->pattern >= 0 && eval_pattern_transform(e, &e->s->pigments[m->pattern], &back, b->loc))
			return -1;
		for (int k = 0; k < 5; k++)
			m->pigment[k] = (float)col[k];
		if (pattern)
			*pattern = eval_xstrdup(p.name);
	}
	free(p.pg.map);
	return 0;
}

/* ---- finish ---- */

static int color3(struct eval *e, const ast_node *n, float out[3])
{
	double c[5];
	if (eval_expect_color(e, n, c))
		return -1;
	for (int i = 0; i < 3; i++)
		out[i] = (float)c[i];
	return 0;
}

static int float_arg(struct eval *e, const ast_node *n, float *out)
{
	double f;
	if (eval_expect_float(e, n, &f))
		return -1;
	*out = (float)f;
	return 0;
}

/* An optional [Bool] or [Amount] after a flag; def when there is none. */
static int optional_float(struct eval *e, struct cursor *c, double def, double *out)
{
	int err = 0;
	const ast_node *arg = eval_next_optional(c, &err);
	*out = def;
	return arg ? eval_expect_float(e, arg, out) : err ? -1 : 0;
}

/* reflection { [COLOR_MIN,] COLOR_MAX [fresnel [Bool]] [falloff F] [exponent F] [metallic [F]] } */
static int reflection_block(struct eval *e, const ast_node *b, scene_material *m)
{
	struct cursor c;
	int err = 0, rc = 0, n = 0;
	float col[2][3];
	double f;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (AST_IS_EXPRESSION(item->kind) && n < 2)
			rc = color3(e, item, col[n++]);
		else if (item->kind == AST_FLAG && item->kw == KW_FRESNEL && (rc = optional_float(e, &c, 1, &f)) == 0)
			m->reflection_fresnel = eval_truth(f);
		else if (item->kind == AST_FLAG && item->kw == KW_METALLIC && (rc = optional_float(e, &c, 1, &f)) == 0)
			m->reflection_metallic = (float)f;
		else if (item->kind == AST_ARG && item->kw == KW_FALLOFF)
			rc = float_arg(e, item->kids[0], &m->reflection_falloff);
		else if (item->kind == AST_ARG && item->kw == KW_EXPONENT)
			rc = float_arg(e, item->kids[0], &m->reflection_exponent);
		else if (rc == 0)
			rc = eval_not_valid(e, item, "a reflection");
	}
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	if (n == 0) {
		eval_error(e, b->loc, "reflection needs a colour or an amount");
		return -1;
	}
	memcpy(m->reflection, col[0], sizeof m->reflection);
	memcpy(m->reflection_max, col[n - 1], sizeof m->reflection_max);
	return 0;
}

static int finish_flag(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m)
{
	double f;
	switch (item->kw) {
	case KW_METALLIC:
		if (optional_float(e, c, 1, &f))
			return -1;
		m->metallic = (float)f;
		return 0;
	case KW_CONSERVE_ENERGY:
		if (optional_float(e, c, 1, &f))
			return -1;
		m->conserve_energy = eval_truth(f);
		return 0;
	default:
		return eval_not_valid(e, item, "a finish");
	}
}

/* diffuse [, Backside]: eclat has no backside illumination. */
static int diffuse(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m)
{
	int err = 0;
	if (float_arg(e, item->kids[0], &m->diffuse))
		return -1;
	const ast_node *back = eval_next_optional(c, &err);
	if (back)
		eval_warn_once(e, back->loc, "diffuse backside", "the backside amount of diffuse is not supported yet; ignored");
	return err ? -1 : 0;
}

static int finish_arg(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m)
{
	const ast_node *a = item->kids[0];
	switch (item->kw) {
	case KW_AMBIENT: return color3(e, a, m->ambient);
	case KW_EMISSION: return color3(e, a, m->emission);
	case KW_DIFFUSE: return diffuse(e, c, item, m);
	case KW_BRILLIANCE: return float_arg(e, a, &m->brilliance);
	case KW_PHONG: return float_arg(e, a, &m->phong);
	case KW_PHONG_SIZE: return float_arg(e, a, &m->phong_size);
	case KW_SPECULAR: return float_arg(e, a, &m->specular);
	case KW_ROUGHNESS:
		m->roughness_set = true;
		return float_arg(e, a, &m->roughness);
	case KW_REFLECTION:
		if (color3(e, a, m->reflection))
			return -1;
		memcpy(m->reflection_max, m->reflection, sizeof m->reflection_max);
		return 0;
	case KW_CRAND: return float_arg(e, a, &m->crand);
	default:
		return eval_not_valid(e, item, "a finish");
	}
}

static int finish_item(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m, bool first)
{
	if (AST_IS_EXPRESSION(item->kind) && first) {
		value v;
		if (eval_expect_kind(e, item, V_FINISH, &v))
			return -1;
		copy_finish(m, &v.mat);
		return 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_IRID) == 0)
		return eval_irid(e, item, m);
	int rc = eval_skip_pov_word(e, c, item);
	if (rc <= 0)
		return rc;
	if (item->kind == AST_BLOCK && item->kw == KW_REFLECTION)
		return reflection_block(e, item, m);
	if (item->kind == AST_ARG)
		return finish_arg(e, c, item, m);
	if (item->kind == AST_FLAG)
		return finish_flag(e, c, item, m);
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) {
		eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
		return 0;
	}
	return eval_not_valid(e, item, "a finish");
}

typedef int material_item_fn(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m,
                              bool first);

/* The items of a finish or interior block, in order, directives run between them. */
static int material_items(struct eval *e, const ast_node *b, scene_material *m, material_item_fn *item_fn)
{
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		rc = item_fn(e, &c, item, m, first);
		first = false;
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* finish { [FINISH_IDENTIFIER] [FINISH_ITEMS...] } */
static int finish_block(struct eval *e, const ast_node *b, scene_material *m)
{
	return material_items(e, b, m, finish_item);
}

/* ---- interior ---- */

/* interior { [INTERIOR_IDENTIFIER] [ior F] [dispersion F] [fade_distance F]
 *            [fade_power F] [fade_color COLOR] [caustics F] [media { }...] } */
static int interior_item(struct eval *e, struct cursor *c, const ast_node *item, scene_material *m, bool first)
{
	int rc = eval_skip_pov_word(e, c, item);
	if (rc <= 0)
		return rc;
	if (AST_IS_EXPRESSION(item->kind) && first) {
		value v;
		if (eval_expect_kind(e, item, V_INTERIOR, &v))
			return -1;
		copy_interior(m, &v.mat);
		return 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_MEDIA)
		return eval_media_interior(e, item, m);
	switch (item->kind == AST_ARG ? item->kw : -1) {
	case KW_IOR: return float_arg(e, item->kids[0], &m->ior);
	case KW_DISPERSION: return float_arg(e, item->kids[0], &m->dispersion);
	case KW_FADE_DISTANCE: return float_arg(e, item->kids[0], &m->fade_distance);
	case KW_FADE_POWER: return float_arg(e, item->kids[0], &m->fade_power);
	case KW_FADE_COLOR: case KW_FADE_COLOUR: return color3(e, item->kids[0], m->fade_color);
	case KW_CAUSTICS: return float_arg(e, item->kids[0], &m->caustics);
	default:
		break;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) {
		eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
		return 0;
	}
	return eval_not_valid(e, item, "an interior");
}

static int interior_block(struct eval *e, const ast_node *b, scene_material *m)
{
	return material_items(e, b, m, interior_item);
}

/* density { ... } as a value (#declare D = density { }): a white pigment. */
int eval_density_value(struct eval *e, const ast_node *b, value *out)
{
	*out = (value){ .kind = V_PIGMENT, .mat = scene_default_material() };
	for (int k = 0; k < 3; k++)
		out->mat.pigment[k] = 1;
	return pigment_block(e, b, &out->mat, NULL);
}

/* density { [DENSITY_IDENTIFIER] [PATTERN] [COLOR_MAP] [MODIFIERS...] }: read as
 * a pigment is (POV-Ray's density_map is its colour map), white by default; a
 * media's densities multiply. */
int eval_media_density(struct eval *e, const ast_node *b, scene_media *md)
{
	scene_material d = scene_default_material();
	for (int k = 0; k < 3; k++)
		d.pigment[k] = 1;
	if (pigment_block(e, b, &d, NULL))
		return -1;
	if (md->n_density == SCENE_MEDIA_DENSITIES) {
		eval_error(e, b->loc, "a media holds at most %d densities", SCENE_MEDIA_DENSITIES);
		return -1;
	}
	for (int k = 0; k < 3; k++)
		if (d.pattern < 0 && !(d.pigment[k] >= 0)) {   /* negative extinction makes light out of nothing */
			eval_error(e, b->loc, "a density must not be negative (%g)", d.pigment[k]);
			return -1;
		}
	md->density[md->n_density] = d.pattern;
	for (int k = 0; k < 3; k++)
		md->density_rgb[md->n_density][k] = d.pigment[k];
	md->n_density++;
	return 0;
}

/* ---- texture and material ---- */

/* texture { [TEXTURE_IDENTIFIER] [pigment {...}] [normal {...}] [finish {...}]
 *           [PATTERN texture_map {...} | PATTERN TEXTURE, TEXTURE] [TRANSFORMATIONS] } */
/* One item of tiles { }: a texture, layered on those before it in its tile,
 * or tile2, after which the textures are the second tile's. */
static int tile_item(struct eval *e, const ast_node *item, scene_material tile[2], int n[2], int *which)
{
	if (item->kind == AST_IDENT && strcmp(item->str, AST_WORD_TILE2) == 0 && !eval_lookup(e, item->str) && *which == 0) {
		*which = 1;
		return 0;
	}
	if (item->kind != AST_BLOCK || item->kw != KW_TEXTURE)
		return eval_not_valid(e, item, "tiles");
	value v;
	if (eval_material_value(e, item, &v))
		return -1;
	eval_apply_texture(e, item->loc, &tile[*which], n[*which]++ > 0, &v.mat);
	eval_value_free(&v);
	return 0;
}

/* tiles { TEXTURE... tile2 TEXTURE... }: POV-Ray's old name for a checker of
 * two textures (Parse_Tiles), the first tile where checker gives 1. */
static int tiles(struct eval *e, const ast_node *b, struct pattern *p, scene_material *m)
{
	scene_material tile[2] = { e->default_mat, e->default_mat };
	int n[2] = { 0, 0 }, which = 0, err = 0, rc = 0;
	struct cursor c;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = tile_item(e, item, tile, n, &which);
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	if (n[0] == 0 || n[1] == 0) {
		eval_error(e, b->loc, n[0] == 0 ? "tiles needs a texture for its first tile"
		                                 : "tiles needs 'tile2' and a texture after it");
		return -1;
	}
	start_pattern(p, b, scene_pattern_name(PATTERN_CHECKER));
	copy_finish(m, &tile[1]);
	for (int i = 1; i >= 0; i--) {
		double col[5];
		for (int k = 0; k < 5; k++)
			col[k] = tile[i].pigment[k];
		list_add(p, col, -1, scene_add_texture(e->s, &tile[i]));
	}
	return 0;
}

static int texture_item(struct eval *e, struct cursor *c, const ast_node *item, struct pattern *p, scene_material *m,
                        bool first)
{
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_TILES) == 0)
		return tiles(e, item, p, m);
	if (is_uv_mapping(e, item)) {   /* the rest of the texture at <u, v, 0> */
		m->uv = SCENE_UV_TEXTURE;
		return 0;
	}
	value v;
	int skip = pattern_word(e, c, item, p);
	if (skip <= 0)
		return skip;
	if ((skip = pattern_start(e, c, item, p)) <= 0)
		return skip;
	if (AST_IS_EXPRESSION(item->kind) && first) {
		if (eval_expect_kind(e, item, V_TEXTURE, &v))
			return -1;
		eval_apply_value(&v, m);
		return 0;
	}
	if (item->kind == AST_BLOCK && (item->kw == KW_PIGMENT || item->kw == KW_FINISH || item->kw == KW_NORMAL))
		return eval_material_block(e, item, m);
	if (p->at && p->kind > 0 && (skip = eval_pattern_modifier(e, c, item, &p->pg)) <= 0)
		return skip;
	if ((skip = image_pattern_block(e, item, p)) <= 0 || (skip = material_map_block(e, item, p)) <= 0 ||
	    (skip = misplaced_image(e, item, "a texture")) <= 0)
		return skip;
	if (item->kind == AST_BLOCK && item->kw == KW_OBJECT)
		return object_pattern(e, item, p, m, OBJECT_LIST_TEXTURES);
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str) &&
	    strcmp(eval_pov_word(item->str), "other") != 0) {
		start_pattern(p, item, item->str);   /* slope { } */
		return 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_TEXTURE_MAP && p->at)
		return map_into(e, item, p);
	if (item->kind == AST_BLOCK && item->kw == KW_TEXTURE && p->at) {   /* checker texture {A} texture {B} */
		if (eval_material_value(e, item, &v))
			return -1;
		if (p->n_list == 0)
			copy_finish(m, &v.mat);
		double c[5];
		for (int k = 0; k < 5; k++)
			c[k] = v.mat.pigment[k];
		list_add(p, c, -1, scene_add_texture(e->s, &v.mat));
		eval_value_free(&v);   /* its pattern's name, when it has one */
		return 0;
	}
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, NULL, item, &t);
	if (rc > 0)   /* a texture's transformations move its patterns */
		m->tex_xf = scene_xform_then(&m->tex_xf, &t);
	if (rc != 0 || is_pattern_modifier(e, item))
		return rc < 0 ? -1 : 0;
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) {
		eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
		return 0;
	}
	return eval_not_valid(e, item, "a texture");
}

/* The end of a texture with a pattern: a pattern of whole textures, its
 * entries the textures of its texture_map or of its list; or, for a pattern
 * eclat does not have, the average of the textures, warned about; a pattern
 * with no textures is ignored, warned about. The texture's transformations (tex_xf) place the pattern and
 * its textures together. */
static void texture_pattern(struct eval *e, struct pattern *p, scene_material *m)
{
	double col[5];
	bool whole = p->kind > 0 && p->kind != PATTERN_IMAGE_MAP && (p->n_list > 0 || (p->has_map && p->map_finish &&
	                                                                             p->map_pigment >= 0));
	if (!whole && p->kind > 0 && p->kind != PATTERN_IMAGE_MAP && !p->has_map) {
		/* POV-Ray's entries are empty: nothing is shaded (black) */
		eval_warning(e, p->at->loc, "'%s' in a texture needs textures (a texture_map, or textures after it); "
		             "ignored", p->name);
		return;
	}
	if (!whole)
		p->kind = -1;
	if (whole && p->n_list > 0 && p->has_map)
		p->n_list = 0;   /* POV-Ray reads the last: a map after the list replaces it */
	pattern_result(e, p, col, &m->texture_map);
	if (p->map_finish)
		copy_finish(m, &p->map_mat);
	for (int k = 0; k < 5; k++)
		m->pigment[k] = (float)col[k];
	m->pattern = m->normal = m->layers = -1;
}

static int texture_block(struct eval *e, const ast_node *b, scene_material *m)
{
	struct pattern p = { 0 };
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		rc = texture_item(e, &c, item, &p, m, first);
		first = false;
	}
	eval_cursor_free(&c);
	if (rc || err) {
		free(p.pg.map);
		return -1;
	}
	if (p.at)
		texture_pattern(e, &p, m);
	if (m->uv == SCENE_UV_TEXTURE)   /* transformations after the texture do not move it */
		m->uv_xf = m->tex_xf;
	free(p.pg.map);
	return 0;
}

/* material { [MATERIAL_IDENTIFIER] [texture {...}] [interior {...}] [TRANSFORMATIONS] } */
static int material_block(struct eval *e, const ast_node *b, scene_material *m)
{
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true, textured = false;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		value v;
		xform t = scene_xform_identity();
		if (AST_IS_EXPRESSION(item->kind) && first) {
			if ((rc = eval_expr(e, item, &v)) == 0 && v.kind != V_MATERIAL)
				rc = eval_not_valid(e, item, "a material");
			else if (rc == 0)
				*m = v.mat, textured = true;
			eval_value_free(&v);
		} else if (item->kind == AST_BLOCK && item->kw == KW_TEXTURE) {
			if ((rc = eval_material_value(e, item, &v)) == 0)
				eval_apply_texture(e, item->loc, m, textured, &v.mat);
			textured = true;
		} else if (item->kind == AST_BLOCK && item->kw == KW_INTERIOR) {
			rc = interior_block(e, item, m);
		} else if ((rc = eval_transform_item(e, NULL, item, &t)) == 0) {
			rc = eval_not_valid(e, item, "a material");
		} else {
			rc = rc < 0 ? -1 : 0;
		}
		first = false;
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* An item of a normal { } after its pattern: the amount right after the
 * pattern, bump_size, accuracy, the pattern's modifiers and transformations.
 * 1 when item is none of them. */
static int normal_item(struct eval *e, struct cursor *c, const ast_node *item, struct pattern *p, bool *amount)
{
	scene_pigment *pg = &p->pg;
	const char *w = item->kind == AST_IDENT && !eval_lookup(e, item->str) ? item->str : NULL;
	int err = 0;
	if (is_uv_mapping(e, item)) {
		p->uv = true;
		return 0;
	}
	if (eval_pattern_is_fractal(pg->kind) && pg->params[0][0] == 0)   /* mandel 50 [Amount]: its arguments first */
		return eval_fractal_modifier(e, c, item, pg);
	if (AST_IS_EXPRESSION(item->kind) && !w && !*amount) {   /* bumps 0.5 */
		*amount = true;
		return eval_expect_float(e, item, &pg->bump_size);
	}
	if (w && (strcmp(w, AST_WORD_BUMP_SIZE) == 0 || strcmp(w, AST_WORD_ACCURACY) == 0)) {
		const ast_node *arg = eval_next_expr(c, &err);
		if (!arg) {
			if (!err)
				eval_error(e, item->loc, "'%s' needs a value", w);
			return -1;
		}
		return eval_expect_float(e, arg, w[0] == 'b' ? &pg->bump_size : &pg->accuracy);
	}
	int rc = eval_pattern_modifier(e, c, item, pg);
	if (rc <= 0)
		return rc;
	xform t = scene_xform_identity();
	rc = eval_transform_item(e, NULL, item, &t);
	if (rc > 0)
		return eval_pattern_transform(e, pg, &t, item->loc);
	return rc < 0 ? -1 : 1;
}

/* slope_map { [Value <Height, Slope>]... }: the normal pattern's map, whose
 * entries hold the height in colour[0] and the slope in colour[1]
 * (kernels/normal.cl). */
static int slope_map(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	free(pg->map);
	pg->map = NULL;
	pg->n_map = 0;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		double v, hs[3];
		if (item->kind != AST_ENTRY || item->n_kids != 2) {
			rc = eval_not_valid(e, item, "a slope_map (entries are [Value <Height, Slope>])");
			break;
		}
		if ((rc = eval_expect_float(e, item->kids[0], &v)) || (rc = eval_expect_vector(e, item->kids[1], hs)))
			break;
		pg->map = eval_xrealloc(pg->map, (pg->n_map + 1) * sizeof *pg->map);
		pg->map[pg->n_map++] = (scene_map_entry){ .value = v, .colour = { (float)hs[0], (float)hs[1] },
		                                          .pigment = -1 };
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

static int normal_block(struct eval *e, const ast_node *b, scene_material *m);

/* The normal of a normal_map's entry: the items after its value, those of a
 * normal { }; its pattern in the pool, or -1 for none (a flat one). */
static int entry_normal(struct eval *e, const ast_node *at, ast_node *const *kids, int n, int *normal)
{
	if (n == 0) {   /* POV-Ray: "No normal type given" */
		eval_error(e, at->loc, "a normal_map entry needs a normal after its value");
		return -1;
	}
	ast_node body = { .kind = AST_BLOCK, .kw = KW_NORMAL, .loc = at->loc, .kids = (ast_node **)kids, .n_kids = n };
	scene_material m = scene_default_material();   /* POV-Ray starts it from the #default normal */
	m.normal = e->default_mat.normal;
	m.normal_amount = e->default_mat.normal_amount;
	if (normal_block(e, &body, &m))
		return -1;
	*normal = m.normal;
	return 0;
}

/* normal_map { [Value NORMAL_ITEMS]... } after a normal's pattern, or one
 * normal { } of a list (checker normal { A } normal { B }): normals of
 * normals, whose entries the pattern picks and blends (texture_normal). */
static int normal_entries(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	if (!pg->normal_map || b->kw == KW_NORMAL_MAP) {   /* a map, or a list's first: the slope_map goes */
		free(pg->map);
		pg->map = NULL;
		pg->n_map = 0;
		pg->normal_map = true;
	}
	if (b->kw == KW_NORMAL) {
		int normal;
		if (entry_normal(e, b, b->kids, b->n_kids, &normal))
			return -1;
		pg->map = eval_xrealloc(pg->map, (pg->n_map + 1) * sizeof *pg->map);
		pg->map[pg->n_map] = (scene_map_entry){ .value = pg->n_map, .pigment = normal, .texture = -1 };
		pg->n_map++;
		return 0;
	}
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		double v = 1;   /* average's weight when left out */
		int first = 0, normal;
		if (item->kind != AST_ENTRY || item->n_kids < 1) {
			rc = eval_not_valid(e, item, "a normal_map (entries are [Value NORMAL_ITEMS])");
			break;
		}
		if (pg->kind != PATTERN_AVERAGE) {
			if ((rc = eval_expect_float(e, item->kids[0], &v)))
				break;
			first = 1;
		} else if (item->n_kids >= 2 && AST_IS_EXPRESSION(item->kids[0]->kind)) {   /* a weight, or a
			                                                                       * declared normal */
			value w;
			if ((rc = eval_expr(e, item->kids[0], &w)))
				break;
			if (w.kind == V_FLOAT) {
				v = w.v[0];
				first = 1;
			}
			eval_value_free(&w);
		}
		if ((rc = entry_normal(e, item, item->kids + first, item->n_kids - first, &normal)))
			break;
		pg->map = eval_xrealloc(pg->map, (pg->n_map + 1) * sizeof *pg->map);
		pg->map[pg->n_map++] = (scene_map_entry){ .value = v, .pigment = normal, .texture = -1 };
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* What goes with a normal's pattern that eclat does not have (bump_map,
 * pigment_pattern...): its amount, modifiers, transformations and blocks,
 * ignored with it. */
static bool ignored_item(struct eval *e, const ast_node *item)
{
	xform t = scene_xform_identity();
	return AST_IS_EXPRESSION(item->kind) || is_pattern_modifier(e, item) || item->kind == AST_BLOCK ||
	       item->kind == AST_FLAG || eval_transform_item(e, NULL, item, &t) > 0;
}

/* object { OBJECT | OBJECT_IDENTIFIER [ITEM_A, ITEM_B] }: POV-Ray's object
 * pattern, 1 inside the object and 0 outside (eval_pattern_object makes the
 * object), so that the list's first item is outside and its second inside
 * (pigments or colours, textures, normals: what) and, as in POV-Ray, no map
 * may follow the block (object_map). */
static int object_pattern(struct eval *e, const ast_node *b, struct pattern *p, scene_material *m,
                          enum object_list what)
{
	static const int kws[] = { KW_PIGMENT, KW_TEXTURE, KW_NORMAL };
	struct cursor c;
	int err = 0, rc = 0, csg = -1;
	start_pattern(p, b, scene_pattern_name(PATTERN_OBJECT));
	eval_cursor_init(&c, e, b);
	const ast_node *item = eval_next(&c, &err);
	if (!item && !err) {
		eval_error(e, b->loc, "an object pattern needs an object first");
		rc = -1;
	}
	if (item && (rc = eval_pattern_object(e, item, &csg)) == 0)
		p->pg.params[0][0] = csg;
	for (int n = 0; rc == 0 && (item = eval_next(&c, &err)) != NULL; n++) {
		bool listed = (item->kind == AST_BLOCK && item->kw == kws[what]) ||
		              (what == OBJECT_LIST_PIGMENTS && AST_IS_EXPRESSION(item->kind));
		if (!listed) {
			rc = eval_not_valid(e, item, "an object pattern's list");
		} else if (n == 2) {   /* POV-Ray's Parse_Blend_List (2) stops there and wants the '}' */
			eval_error(e, item->loc, "an object pattern's list holds two items, outside and inside; "
			           "found a third");
			rc = -1;
		}
		if (rc)
			break;
		if (what == OBJECT_LIST_PIGMENTS)
			rc = pigment_item(e, &c, item, p, m);
		else if (what == OBJECT_LIST_TEXTURES)
			rc = texture_item(e, &c, item, p, m, false);
		else
			rc = normal_entries(e, item, &p->pg);
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* p as a copy of the normal pattern base (its slope_map too), started at at. */
static void copy_normal(struct eval *e, struct pattern *p, int base_index, const ast_node *at)
{
	const scene_pigment *base = &e->s->pigments[base_index];
	p->at = at;
	p->kind = base->kind;
	p->pg = *base;
	p->pg.map = base->n_map ? eval_xrealloc(NULL, base->n_map * sizeof *base->map) : NULL;
	if (base->n_map)
		memcpy(p->pg.map, base->map, base->n_map * sizeof *base->map);
}

/* normal { [NORMAL_IDENTIFIER] [PATTERN [Amount]] [bump_size Amount]
 *          [accuracy Accuracy] [PATTERN_MODIFIER...] [TRANSFORMATION...] }:
 * the pattern perturbs the surface normal where the kernels shade
 * (pattern_perturb); a camera's perturbs its rays (eval_world.c). Without a
 * pattern of its own it modifies the normal m has (normal { slope_map { } }
 * after a texture's normal), as POV-Ray's does; a new pattern is placed by
 * its own transformations only, not by those m's texture took before it. */
/* What a pattern written in a normal starts from: POV-Ray's Parse_Pattern
 * changes only the kind of the normal it is given, which keeps its amount and
 * its transformations and warps; a normal without a pattern yet gives the
 * amount its bump_size set (#default { normal { bump_size 1.5 } }). */
typedef struct {
	double amount;
	scene_warp warps[SCENE_MAX_WARPS];
	int n_warps;
} normal_base;

static normal_base normal_base_of(const struct eval *e, const scene_material *m)
{
	normal_base nb = { .amount = m->normal_amount > 0 ? m->normal_amount : 0.5 };
	if (m->normal >= 0 && m->normal < e->s->n_pigments) {
		const scene_pigment *pg = &e->s->pigments[m->normal];
		nb.amount = pg->bump_size;
		nb.n_warps = pg->n_warps;
		memcpy(nb.warps, pg->warps, sizeof nb.warps);
	}
	return nb;
}

static void normal_restart(scene_pigment *pg, const normal_base *nb)
{
	pg->bump_size = nb->amount;
	pg->accuracy = 0.02;
	if (nb->n_warps > 0 && pg->n_warps == 0) {
		pg->n_warps = nb->n_warps;
		memcpy(pg->warps, nb->warps, sizeof pg->warps);
	}
}

static int normal_block(struct eval *e, const ast_node *b, scene_material *m)
{
	struct pattern p = { .kind = -1 };
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true, amount = false;
	const ast_node *item;
	const normal_base nb = normal_base_of(e, m);
	double bare_amount = 0;   /* bump_size in a normal without a pattern */
	if (m->normal >= 0 && m->normal < e->s->n_pigments)
		copy_normal(e, &p, m->normal, b);
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		value v;
		if (is_uv_mapping(e, item)) {   /* a declared normal may follow it */
			p.uv = true;
			continue;
		}
		if (item->kind == AST_BLOCK && item->kw == KW_OBJECT) {
			rc = object_pattern(e, item, &p, m, OBJECT_LIST_NORMALS);
			normal_restart(&p.pg, &nb);
			amount = false;
			first = false;
			continue;
		}
		if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_BUMP_MAP) == 0) {
			start_pattern(&p, item, AST_WORD_BUMP_MAP);
			normal_restart(&p.pg, &nb);   /* its bump_size, or the amount after it, may change it */
			amount = false;
			rc = eval_bump_map(e, item, &p.pg);
			first = false;
			continue;
		}
		if (first && AST_IS_EXPRESSION(item->kind) && !eval_pov_word_item(e, item) &&
		    (item->kind != AST_IDENT || eval_lookup(e, item->str))) {   /* a declared normal */
			if ((rc = eval_expect_kind(e, item, V_NORMAL, &v)) == 0 && v.mat.normal >= 0) {
				free(p.pg.map);   /* the normal m had, replaced */
				copy_normal(e, &p, v.mat.normal, item);
				amount = true;
			}
		} else if ((rc = pattern_start(e, &c, item, &p)) <= 0) {
			amount = false;
			if (rc == 0 && p.kind > 0)
				normal_restart(&p.pg, &nb);
		} else if (p.at && p.kind > 0 && (rc = normal_item(e, &c, item, &p, &amount)) <= 0) {
			;
		} else if (p.at && p.kind > 0 && item->kind == AST_BLOCK && item->kw == KW_UNKNOWN &&
		           strcmp(item->str, AST_WORD_SLOPE_MAP) == 0) {
			rc = slope_map(e, item, &p.pg);
		} else if ((rc = misplaced_image(e, item, "a normal")) <= 0) {
			;
		} else if ((rc = image_pattern_block(e, item, &p)) <= 0) {
			amount = false;
			normal_restart(&p.pg, &nb);
		} else if (!(p.at && p.kind > 0) && item->kind == AST_IDENT && !eval_lookup(e, item->str) &&
		           strcmp(item->str, AST_WORD_BUMP_SIZE) == 0) {
			const ast_node *arg = eval_next_expr(&c, &err);
			if (!arg && !err)
				eval_error(e, item->loc, "'bump_size' needs a value");
			rc = arg ? eval_expect_float(e, arg, &bare_amount) : -1;
		} else if ((rc = pattern_word(e, &c, item, &p)) <= 0) {
			;   /* a pattern eclat does not have (warned below), or another POV-Ray word (warned) */
		} else if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) {
			eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
			rc = 0;
		} else if (p.at && p.kind == PATTERN_OBJECT && item->kind == AST_BLOCK && item->kw == KW_NORMAL_MAP) {
			rc = object_map(e, item);
		} else if (p.at && p.kind > 0 && p.kind != PATTERN_FACETS && item->kind == AST_BLOCK &&
		           (item->kw == KW_NORMAL_MAP || item->kw == KW_NORMAL)) {
			rc = normal_entries(e, item, &p.pg);
		} else if (item->kind == AST_BLOCK && (item->kw == KW_NORMAL_MAP || item->kw == KW_NORMAL)) {
			eval_warn_once(e, item->loc, "normal_map", "normals of normals (%s) are not supported yet; "
			               "this normal is ignored", item->kw == KW_NORMAL ? "checker normal { } normal { }"
			                                                            : "normal_map");
			p.kind = -1;   /* the pattern alone would be the wrong bumps */
			p.at = p.at ? p.at : item;
			snprintf(p.name, sizeof p.name, "%s", "");
			rc = 0;
		} else if (!(p.at && p.kind > 0) && ignored_item(e, item)) {
			rc = 0;   /* it goes with a pattern eclat does not have, warned about */
		} else {
			rc = eval_not_valid(e, item, "a normal");
		}
		first = false;
	}
	eval_cursor_free(&c);
	if (rc || err) {
		free(p.pg.map);
		return -1;
	}
	if (p.at && p.kind == PATTERN_AVERAGE && !p.pg.normal_map)   /* POV-Ray: "Average must have map." */
		p.kind = -1;
	if (p.at && p.kind == PATTERN_SLOPE)   /* a normal of the normal's own slope: not yet */
		p.kind = -1;
	if (p.at && p.kind > 0 && eval_pavement_check(e, &p.pg, p.at->loc)) {
		free(p.pg.map);
		return -1;
	}
	if (p.at && p.kind < 0 && p.name[0])
		eval_warn_once(e, p.at->loc, p.name, "pattern '%s' is not supported yet in a normal; ignored", p.name);
	p.pg.uv |= p.uv;
	xform id = scene_xform_identity();
	bool moved = p.at != b && m->uv == SCENE_UV_NONE && !p.pg.uv && memcmp(&m->tex_xf, &id, sizeof id) != 0;
	if (!(p.at && p.kind > 0) && bare_amount != 0)
		m->normal_amount = (float)bare_amount;
	if (p.at && p.kind > 0) {
		m->normal = scene_add_pigment(e->s, &p.pg);
		if (moved) {   /* so that tex_xf brings it back to where it is written */
			xform back = eval_xform_inverse(&m->tex_xf);
			return eval_pattern_transform(e, &e->s->pigments[m->normal], &back, b->loc);
		}
	} else {
		free(p.pg.map);
	}
	return 0;
}

int eval_material_block(struct eval *e, const ast_node *b, scene_material *m)
{
	switch (b->kw) {
	case KW_PIGMENT: return pigment_block(e, b, m, NULL);
	case KW_FINISH: return finish_block(e, b, m);
	case KW_TEXTURE: return texture_block(e, b, m);
	case KW_INTERIOR: return interior_block(e, b, m);
	case KW_MATERIAL: return material_block(e, b, m);
	case KW_NORMAL: return normal_block(e, b, m);
	default: return eval_not_valid(e, b, "a texture");
	}
}

/* #declare T = texture { A } texture { B }: B layered on A. */
static int layers(struct eval *e, const ast_node *b, value *out)
{
	*out = (value){ .kind = V_TEXTURE, .mat = e->default_mat };
	for (int i = 0; i < b->n_kids; i++) {
		value v;
		int rc = b->kids[i]->kw == KW_TEXTURE ? eval_material_value(e, b->kids[i], &v) : layers(e, b->kids[i], &v);
		if (rc)
			return -1;
		eval_apply_texture(e, b->kids[i]->loc, &out->mat, i > 0, &v.mat);
	}
	return 0;
}

int eval_material_value(struct eval *e, const ast_node *b, value *out)
{
	static const struct { int kw; val_kind kind; } kinds[] = {
		{ KW_PIGMENT, V_PIGMENT }, { KW_FINISH, V_FINISH }, { KW_TEXTURE, V_TEXTURE },
		{ KW_NORMAL, V_NORMAL }, { KW_INTERIOR, V_INTERIOR }, { KW_MATERIAL, V_MATERIAL },
	};
	if (b->kw == KW_UNKNOWN && b->str && strcmp(b->str, "layers") == 0)
		return layers(e, b, out);
	if (b->kw == KW_COLOR_MAP || b->kw == KW_COLOUR_MAP || b->kw == KW_PIGMENT_MAP || b->kw == KW_TEXTURE_MAP ||
	    b->kw == KW_NORMAL_MAP)
		return map_block(e, b, out);
	*out = (value){ .kind = V_NONE, .mat = e->default_mat };
	for (size_t i = 0; i < sizeof kinds / sizeof *kinds; i++)
		if (kinds[i].kw == b->kw)
			out->kind = kinds[i].kind;
	if (b->kw == KW_PIGMENT)
		return pigment_block(e, b, &out->mat, &out->str);
	return eval_material_block(e, b, &out->mat);
}

/* #default { texture {...} | pigment {...} | finish {...} }: the texture objects
 * start from afterwards. */
int eval_default(struct eval *e, const ast_node *d)
{
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, d);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (item->kind == AST_BLOCK && (item->kw == KW_TEXTURE || item->kw == KW_PIGMENT ||
		                                item->kw == KW_FINISH || item->kw == KW_NORMAL)) {
			scene_material m = e->default_mat;
			if ((rc = eval_material_block(e, item, &m)) == 0)
				e->default_mat = m;
		} else {
			rc = eval_not_valid(e, item, "#default");
		}
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}
