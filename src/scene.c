/* scene.c: scene containers, defaults and affine transforms. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"
#include "shape.h"

xform scene_xform_identity(void)
{
	return (xform){ { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } } };
}

xform scene_xform_translate(const double v[3])
{
	xform t = scene_xform_identity();
	for (int i = 0; i < 3; i++)
		t.m[i][3] = v[i];
	return t;
}

xform scene_xform_scale(const double v[3])
{
	xform t = scene_xform_identity();
	for (int i = 0; i < 3; i++)
		t.m[i][i] = v[i];
	return t;
}

/* One axis of POV-Ray's rotation (Compute_Rotation_Transform): the usual matrix,
 * which in a left-handed frame turns clockwise when seen down the positive axis. */
static xform rotate_axis(int axis, double deg)
{
	xform t = scene_xform_identity();
	double a = deg * M_PI / 180.0, c = cos(a), s = sin(a);
	int i = (axis + 1) % 3, j = (axis + 2) % 3;
	t.m[i][i] = c;
	t.m[i][j] = -s;
	t.m[j][i] = s;
	t.m[j][j] = c;
	return t;
}

xform scene_xform_rotate(const double deg[3])
{
	xform t = scene_xform_identity();
	for (int axis = 0; axis < 3; axis++) {
		xform r = rotate_axis(axis, deg[axis]);
		t = scene_xform_then(&t, &r);
	}
	return t;
}

xform scene_xform_then(const xform *a, const xform *b)
{
	xform r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double v = j == 3 ? b->m[i][3] : 0;
			for (int k = 0; k < 3; k++)
				v += b->m[i][k] * a->m[k][j];
			r.m[i][j] = v;
		}
	return r;
}

void scene_xform_point(const xform *t, const double p[3], double out[3])
{
	double r[3];
	for (int i = 0; i < 3; i++)
		r[i] = t->m[i][0] * p[0] + t->m[i][1] * p[1] + t->m[i][2] * p[2] + t->m[i][3];
	memcpy(out, r, sizeof r);
}

void scene_xform_vector(const xform *t, const double v[3], double out[3])
{
	double r[3];
	for (int i = 0; i < 3; i++)
		r[i] = t->m[i][0] * v[0] + t->m[i][1] * v[1] + t->m[i][2] * v[2];
	memcpy(out, r, sizeof r);
}

void scene_init(scene *s)
{
	memset(s, 0, sizeof *s);
	s->camera = scene_default_camera();
	s->adc_bailout = 1.0f / 255.0f;
	s->film_gamma = 1;
	s->noise_generator = 2;
	s->number_of_waves = 10;
	s->irid_wavelength[0] = 0.70f;
	s->irid_wavelength[1] = 0.52f;
	s->irid_wavelength[2] = 0.48f;
	s->background_ft[1] = 1;

	for (int i = 0; i < 3; i++)
		s->ambient_light[i] = 1;
}

int scene_noise_generator(const scene *s, const scene_pigment *pg)
{
	return pg->noise_generator ? pg->noise_generator : s->noise_generator;
}

static void *grow(void *p, int *cap, size_t size)
{
	*cap = *cap ? 2 * *cap : 16;
	p = realloc(p, *cap * size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return p;
}

void scene_add_object(scene *s, const scene_object *o)
{
	if (s->n_objects == s->cap_objects)
		s->objects = grow(s->objects, &s->cap_objects, sizeof *o);
	s->objects[s->n_objects++] = *o;
}

void scene_add_light(scene *s, const scene_light *l)
{
	if (s->n_lights == s->cap_lights)
		s->lights = grow(s->lights, &s->cap_lights, sizeof *l);
	s->lights[s->n_lights++] = *l;
}

void scene_add_fog(scene *s, const scene_fog *f)
{
	if (s->n_fogs == s->cap_fogs)
		s->fogs = grow(s->fogs, &s->cap_fogs, sizeof *f);
	s->fogs[s->n_fogs++] = *f;
}

int scene_add_media(scene *s, const scene_media *m)
{
	if (s->n_media == s->cap_media)
		s->media = grow(s->media, &s->cap_media, sizeof *m);
	s->media[s->n_media] = *m;
	return s->n_media++;
}

scene_media scene_default_media(void)
{
	return (scene_media){ .type = SCENE_SCATTER_ISOTROPIC, .extinction = 1, .method = 3, .intervals = 1,
	                      .min_samples = 10, .max_samples = 10, .confidence = 0.9, .variance = 1.0 / 128,
	                      .ratio = 0.9, .aa_threshold = 0.1, .aa_level = 3, .xf = scene_xform_identity(), .prev = -1 };
}

void scene_add_rainbow(scene *s, const scene_rainbow *r)
{
	if (s->n_rainbows == s->cap_rainbows)
		s->rainbows = grow(s->rainbows, &s->cap_rainbows, sizeof *r);
	s->rainbows[s->n_rainbows++] = *r;
}

scene_fog scene_default_fog(void)
{
	return (scene_fog){ .type = SCENE_FOG_CONSTANT, .up = { 0, 1, 0 }, .octaves = 6, .omega = 0.5, .lambda = 2,
	                    .turb_depth = 0.5 };
}

int scene_add_mesh(scene *s, scene_mesh *m)
{
	if (s->n_meshes == s->cap_meshes)
		s->meshes = grow(s->meshes, &s->cap_meshes, sizeof *m);
	s->meshes[s->n_meshes] = *m;
	return s->n_meshes++;
}

int scene_add_outline(scene *s, const scene_outline *o)
{
	if (s->n_outlines == s->cap_outlines)
		s->outlines = grow(s->outlines, &s->cap_outlines, sizeof *o);
	s->outlines[s->n_outlines] = *o;
	return s->n_outlines++;
}

int scene_add_poly(scene *s, const scene_poly *p)
{
	if (s->n_polys == s->cap_polys)
		s->polys = grow(s->polys, &s->cap_polys, sizeof *p);
	s->polys[s->n_polys] = *p;
	return s->n_polys++;
}

int scene_add_blob(scene *s, const scene_blob *b)
{
	if (s->n_blobs == s->cap_blobs)
		s->blobs = grow(s->blobs, &s->cap_blobs, sizeof *b);
	s->blobs[s->n_blobs] = *b;
	return s->n_blobs++;
}

int scene_add_pigment(scene *s, const scene_pigment *p)
{
	if (s->n_pigments == s->cap_pigments)
		s->pigments = grow(s->pigments, &s->cap_pigments, sizeof *p);
	s->pigments[s->n_pigments] = *p;
	return s->n_pigments++;
}

int scene_add_texture(scene *s, const scene_material *m)
{
	if (s->n_textures == s->cap_textures)
		s->textures = grow(s->textures, &s->cap_textures, sizeof *m);
	s->textures[s->n_textures] = *m;
	return s->n_textures++;
}

int scene_add_image(scene *s, const scene_image *im)
{
	if (s->n_images == s->cap_images)
		s->images = grow(s->images, &s->cap_images, sizeof *im);
	s->images[s->n_images] = *im;
	return s->n_images++;
}

void scene_mesh_free(scene_mesh *m)
{
	free(m->v);
	free(m->nrm);
	free(m->uv);
	free(m->face);
	free(m->face_nrm);
	free(m->face_uv);
	free(m->face_mat);
	free(m->mats);
}

int scene_add_camera_mesh(scene *s, const scene_camera_mesh *m)
{
	if (s->n_camera_meshes == s->cap_camera_meshes)
		s->camera_meshes = grow(s->camera_meshes, &s->cap_camera_meshes, sizeof *m);
	s->camera_meshes[s->n_camera_meshes] = *m;
	return s->n_camera_meshes++;
}

int scene_add_csg(scene *s, const scene_csg *c)
{
	if (s->n_csgs == s->cap_csgs)
		s->csgs = grow(s->csgs, &s->cap_csgs, sizeof *c);
	s->csgs[s->n_csgs] = *c;
	return s->n_csgs++;
}

void scene_free(scene *s)
{
	for (int i = 0; i < s->n_functions; i++)
		free(s->functions[i].ops);
	free(s->functions);
	for (int i = 0; i < s->n_csgs; i++)
		free(s->csgs[i].ops);
	free(s->csgs);
	for (int i = 0; i < s->n_meshes; i++)
		scene_mesh_free(&s->meshes[i]);
	free(s->meshes);
	for (int i = 0; i < s->n_outlines; i++) {
		free(s->outlines[i].edge);
		free(s->outlines[i].glyph);
	}
	free(s->outlines);
	for (int i = 0; i < s->n_blobs; i++)
		free(s->blobs[i].part);
	free(s->blobs);
	free(s->camera_meshes);
	for (int i = 0; i < s->n_polys; i++)
		free(s->polys[i].c);
	free(s->polys);
	free(s->objects);
	free(s->lights);
	free(s->fogs);
	free(s->rainbows);
	free(s->media);
	for (int i = 0; i < s->n_pigments; i++)
		free(s->pigments[i].map);
	free(s->pigments);
	free(s->textures);
	free(s->sky_layers);
	for (int i = 0; i < s->n_images; i++) {
		free(s->images[i].key);
		free(s->images[i].rgba);
		free(s->images[i].filter);
	}
	free(s->images);
	memset(s, 0, sizeof *s);
}

scene_material scene_default_material(void)
{
	return (scene_material){
		.pigment = { 0, 0, 0, 0, 0 },
		.pattern = -1,
		.normal = -1,
		.tex_xf = scene_xform_identity(),
		.texture_map = -1,
		.layers = -1,
		.below = -1,
		.interior_xf = scene_xform_identity(),
		.ambient = { 0.1f, 0.1f, 0.1f },
		.diffuse = 0.6f,
		.brilliance = 1,
		.phong_size = 40,
		.roughness = 0.05f,
		.reflection_falloff = 1,
		.reflection_exponent = 1,
		.ior = 1,
		.dispersion = 1,
	};
}

scene_light scene_default_light(void)
{
	return (scene_light){
		.kind = LIGHT_POINT,
		.point_at = { 0, 0, 1 },
		.radius = 30,
		.falloff = 45,
		.adaptive = 100,   /* POV-Ray: without adaptive, every light of the grid is tested */
		.looks_like = -1,
		.loc = SRC_NOWHERE,
	};
}

scene_camera scene_default_camera(void)
{
	return (scene_camera){
		.location = { 0, 0, 0 },
		.direction = { 0, 0, 1 },
		.right = { 1.33, 0, 0 },
		.up = { 0, 1, 0 },
		.loc = SRC_NOWHERE,
		.focal_distance = -1,   /* not yet known */
		.confidence = 0.9,
		.variance = 1.0 / 10000,
		.type = CAMERA_PERSPECTIVE,
		.angle = 90,
		.h_angle = 360,
		.v_angle = 180,
		.normal = -1,
	};
}

const char *scene_camera_name(int type)
{
	static const char *const names[CAMERA_TYPES] = {   /* ORDER CAMERA_ */
		"perspective", "orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic",
		"cylinder 1", "cylinder 2", "cylinder 3", "cylinder 4", "spherical", "mesh_camera",
	};
	return type >= 0 && type < CAMERA_TYPES ? names[type] : "unknown";
}

static double dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double a[3], const double b[3], double out[3])
{
	double r[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
	memcpy(out, r, sizeof r);
}

static void scale_to(double v[3], double len)
{
	double l = sqrt(dot(v, v));
	for (int i = 0; i < 3 && l > 0; i++)
		v[i] *= len / l;
}

int scene_camera_look_at(scene_camera *c, const double p[3], const double sky[3])
{
	double dl = sqrt(dot(c->direction, c->direction));
	double ul = sqrt(dot(c->up, c->up));
	double rl = sqrt(dot(c->right, c->right));
	double t[3];
	cross(c->up, c->direction, t);
	double handedness = dot(t, c->right);

	double d[3] = { p[0] - c->location[0], p[1] - c->location[1], p[2] - c->location[2] };
	if (dot(d, d) < 1e-10)
		return -1;
	scale_to(d, 1);
	double r[3];
	cross(sky, d, r);
	/* sky parallel to the view: keep the old right, as POV-Ray does (and warns) */
	int parallel = fabs(r[0]) < 1e-10 && fabs(r[1]) < 1e-10 && fabs(r[2]) < 1e-10;
	if (parallel)
		memcpy(r, c->right, sizeof r);
	scale_to(r, 1);
	cross(d, r, c->up);
	scale_to(c->up, ul);
	memcpy(c->direction, d, sizeof d);
	scale_to(c->direction, dl);
	memcpy(c->right, r, sizeof r);
	scale_to(c->right, handedness > 0 ? rl : -rl);
	return parallel;
}

/* %.6g, with round-off next to zero (and -0) printed as 0, so golden files do
 * not depend on the last bits of the math library. */
static void num(FILE *out, double v)
{
	fprintf(out, "%.6g", fabs(v) < 1e-9 ? 0.0 : v);
}

static void vec(FILE *out, const char *label, const double v[3])
{
	fprintf(out, *label ? " %s <" : " <", label);
	for (int i = 0; i < 3; i++) {
		num(out, v[i]);
		fputs(i < 2 ? ", " : ">", out);
	}
}

static void color3(FILE *out, const char *label, const float c[3])
{
	double v[3] = { c[0], c[1], c[2] };
	vec(out, label, v);
}

static bool same3(const float a[3], const float b[3])
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static void fnum(FILE *out, const char *label, double v)
{
	fprintf(out, " %s ", label);
	num(out, v);
}

/* The finish and interior items that differ from POV-Ray's defaults: scenes that
 * set none print as they did before these existed. */
static void material_extras(FILE *out, const scene_material *m)
{
	scene_material d = scene_default_material();
	if (!same3(m->ambient, d.ambient))
		color3(out, "ambient", m->ambient);
	static const struct { const char *name; size_t at; } floats[] = {
		{ "brilliance", offsetof(scene_material, brilliance) },
		{ "phong", offsetof(scene_material, phong) },
		{ "phong_size", offsetof(scene_material, phong_size) },
		{ "specular", offsetof(scene_material, specular) },
		{ "roughness", offsetof(scene_material, roughness) },
		{ "metallic", offsetof(scene_material, metallic) },
		{ "reflection_metallic", offsetof(scene_material, reflection_metallic) },
		{ "reflection_falloff", offsetof(scene_material, reflection_falloff) },
		{ "reflection_exponent", offsetof(scene_material, reflection_exponent) },
		{ "ior", offsetof(scene_material, ior) },
		{ "dispersion", offsetof(scene_material, dispersion) },
		{ "fade_distance", offsetof(scene_material, fade_distance) },
		{ "fade_power", offsetof(scene_material, fade_power) },
	};
	for (size_t i = 0; i < sizeof floats / sizeof *floats; i++) {
		float v = *(const float *)((const char *)m + floats[i].at);
		float dv = *(const float *)((const char *)&d + floats[i].at);
		if (v != dv)
			fnum(out, floats[i].name, v);
	}
	if (!same3(m->reflection, d.reflection) || !same3(m->reflection_max, d.reflection_max)) {
		color3(out, "reflection", m->reflection);
		color3(out, "reflection_max", m->reflection_max);
	}
	if (m->reflection_fresnel)
		fputs(" fresnel", out);
	if (m->roughness_set)
		fputs(" roughness_set", out);
	if (m->conserve_energy)
		fputs(" conserve_energy", out);
	if (!same3(m->fade_color, d.fade_color))
		color3(out, "fade_color", m->fade_color);
}

static void material(FILE *out, const scene_material *m)
{
	fputs(" pigment <", out);
	for (int i = 0; i < 5; i++) {
		num(out, m->pigment[i]);
		fputs(i < 4 ? ", " : ">", out);
	}
	if (m->pattern >= 0)
		fprintf(out, " pattern %d", m->pattern);
	if (m->normal >= 0)
		fprintf(out, " normal %d", m->normal);
	if (m->texture_map >= 0)
		fprintf(out, " texture_map %d", m->texture_map);
	if (m->layers >= 0)
		fprintf(out, " layers %d", m->layers);
	if (m->below >= 0)
		fprintf(out, " below %d", m->below);
	fputs(" diffuse ", out);
	num(out, m->diffuse);
	double e[3] = { m->emission[0], m->emission[1], m->emission[2] };
	vec(out, "emission", e);
	material_extras(out, m);
}

static bool identity(const xform *t)
{
	xform i = scene_xform_identity();
	return memcmp(&i, t, sizeof i) == 0;
}

/* POV-Ray's matrix <A..L>: what "matrix" would read back. */
static void matrix(FILE *out, const xform *t)
{
	fputs(" matrix <", out);
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 3; j++) {
			num(out, t->m[j][i]);
			fputs(i == 3 && j == 2 ? ">" : ", ", out);
		}
}

static void flags(FILE *out, int f)
{
	static const char *const names[] = { "no_shadow", "no_image", "no_reflection", "hollow", "double_illuminate" };
	for (int i = 0; i < 5; i++)
		if (f & (1 << i))
			fprintf(out, " %s", names[i]);
}

void scene_dump_num(FILE *out, double v)
{
	num(out, v);
}

void scene_dump_vec(FILE *out, const char *label, const double v[3])
{
	vec(out, label, v);
}

void scene_dump_xform(FILE *out, const xform *t)
{
	if (!identity(t))
		matrix(out, t);
}

static void dump_object(FILE *out, const scene_object *o)
{
	fprintf(out, "%s:%d:%d: ", diag_source_name(o->loc.file), o->loc.line, o->loc.col);
	shape_of(o)->dump(out, o);
	material(out, &o->material);
	flags(out, o->flags);
	fputc('\n', out);
}

/* A CSG object: its leaves (the objects above) and its program, in postfix:
 * "leaf 0", "not", "and 2", "or 2" (merge), "union 2". */
static void dump_csg(FILE *out, int index, const scene_csg *g)
{
	static const char *const ops[] = { "", "leaf", "not", "and", "or", "union" };
	fprintf(out, "%s:%d:%d: csg %d: objects %d to %d%s:", diag_source_name(g->loc.file), g->loc.line, g->loc.col,
	        index, g->first, g->first + g->n_leaves - 1, g->pattern ? " (an object pattern's)" : "");
	for (int i = 0; i < g->n_ops; i++) {
		int op = g->ops[i] >> CSG_OP_SHIFT, arg = g->ops[i] & ((1 << CSG_OP_SHIFT) - 1);
		fprintf(out, " %s", op >= 1 && op <= 5 ? ops[op] : "?");
		if (op != CSG_NOT)
			fprintf(out, arg == (1 << CSG_OP_SHIFT) - 1 ? " none" : " %d", arg);
	}
	fputc('\n', out);
}

/* A mesh once, in object space: its faces with their vertices (and normals,
 * uvs, texture), then its textures. */
static void dump_mesh(FILE *out, int index, const scene_mesh *m)
{
	fprintf(out, "%s:%d:%d: mesh %d: %d vertices %d faces %d normals %d uvs %d textures",
	        diag_source_name(m->loc.file), m->loc.line, m->loc.col, index, m->n_v, m->n_faces, m->n_nrm, m->n_uv,
	        m->n_mats);
	if (m->has_inside_vector)
		vec(out, "inside_vector", m->inside_vector);
	fputc('\n', out);
	for (int f = 0; f < m->n_faces; f++) {
		fputs("  face", out);
		for (int k = 0; k < 3; k++)
			vec(out, "", m->v[m->face[f][k]]);
		for (int k = 0; m->face_nrm && k < 3; k++)
			vec(out, k == 0 ? "normals" : "", m->nrm[m->face_nrm[f][k]]);
		for (int k = 0; m->face_uv && k < 3; k++) {
			const double *uv = m->uv[m->face_uv[f][k]];
			fprintf(out, "%s <", k == 0 ? " uv" : "");
			num(out, uv[0]);
			fputs(", ", out);
			num(out, uv[1]);
			fputc('>', out);
		}
		if (m->face_mat && m->face_mat[f] >= 0)
			fprintf(out, " texture %d", m->face_mat[f]);
		fputc('\n', out);
	}
	for (int t = 0; t < m->n_mats; t++) {
		fprintf(out, "  texture %d:", t);
		material(out, &m->mats[t]);
		fputc('\n', out);
	}
}

static void dump_light(FILE *out, const scene_light *l)
{
	double col[3] = { l->color[0], l->color[1], l->color[2] };
	fputs("light_source", out);
	vec(out, "", l->position);
	vec(out, "color", col);
	if (l->kind == LIGHT_SPOT) {
		fputs(" spotlight", out);
		vec(out, "point_at", l->point_at);
		fnum(out, "radius", l->radius);
		fnum(out, "falloff", l->falloff);
		fnum(out, "tightness", l->tightness);
	} else if (l->kind == LIGHT_PARALLEL) {
		fputs(" parallel", out);
		vec(out, "point_at", l->point_at);
	}
	if (l->area) {
		vec(out, "area_light", l->axis1);
		vec(out, "", l->axis2);
		fprintf(out, " %d %d adaptive %d%s%s%s", l->size1, l->size2, l->adaptive, l->jitter ? " jitter" : "",
		        l->circular ? " circular" : "", l->orient ? " orient" : "");
	}
	if (l->shadowless)
		fputs(" shadowless", out);
	if (l->media_attenuation)
		fputs(" media_attenuation", out);
	if (l->fade_distance != 0 || l->fade_power != 0) {
		fnum(out, "fade_distance", l->fade_distance);
		fnum(out, "fade_power", l->fade_power);
	}
	if (l->looks_like >= 0)
		fprintf(out, " looks_like %d", l->looks_like);
	fputc('\n', out);
}

/* ORDER: PATTERN_ in kernels/shared.h. */
static const char *const pattern_names[] = {
	"solid", "agate", "aoi", "boxed", "bozo", "brick", "bumps", "cells", "checker", "crackle", "cubic",
	"cylindrical", "dents", "facets", "gradient", "granite", "hexagon", "leopard", "marble", "onion",
	"planar", "quilted", "radial", "ripples", "spherical", "spiral1", "spiral2", "spotted", "square",
	"triangular", "waves", "wood", "wrinkles", "image_map", "function",
	"average", "slope",
	"mandel", "julia", "magnet", "image_pattern", "bump_map",
	"material_map", "density_file", "tiling", "pavement", "object",
};
_Static_assert(sizeof pattern_names / sizeof *pattern_names == PATTERN_COUNT, "a name for each pattern");

const char *scene_pattern_name(int kind)
{
	return kind >= 0 && kind < PATTERN_COUNT ? pattern_names[kind] : "?";
}

/* The pattern pigments that materials use, and those their maps nest, once
 * each; used: 1 for a pigment, 2 for a pattern of whole textures. The textures
 * of the pool that those hold and layers are marked in used_tex. */
static void mark_material(const scene *s, const scene_material *m, char *used, bool *used_tex);

static void mark_pigment(const scene *s, int i, char *used, bool *used_tex, bool textures)
{
	if (i < 0 || i >= s->n_pigments || used[i])
		return;
	used[i] = textures ? 2 : 1;
	for (int k = 0; k < s->pigments[i].n_map; k++) {
		const scene_map_entry *e = &s->pigments[i].map[k];
		if (!textures) {
			mark_pigment(s, e->pigment, used, used_tex, false);
		} else if (e->texture >= 0 && e->texture < s->n_textures && !used_tex[e->texture]) {
			used_tex[e->texture] = true;
			mark_material(s, &s->textures[e->texture], used, used_tex);
		}
	}
}

static void mark_material(const scene *s, const scene_material *m, char *used, bool *used_tex)
{
	mark_pigment(s, m->pattern, used, used_tex, false);
	mark_pigment(s, m->normal, used, used_tex, false);
	mark_pigment(s, m->texture_map, used, used_tex, true);
	int layers[2] = { m->layers, m->below };
	for (int i = 0; i < 2; i++)
		if (layers[i] >= 0 && layers[i] < s->n_textures && !used_tex[layers[i]]) {
			used_tex[layers[i]] = true;
			mark_material(s, &s->textures[layers[i]], used, used_tex);
		}
}

static void dump_pigment(FILE *out, const scene *s, int index, const scene_pigment *pg, bool textures)
{
	fprintf(out, "pigment %d %s", index, scene_pattern_name(pg->kind));
	double params[8];
	memcpy(params, pg->params, sizeof params);
	fputs(" params", out);
	for (int i = 0; i < 8; i++) {
		fputc(' ', out);
		num(out, params[i]);
	}
	fprintf(out, " wave %d noise_generator %d", pg->wave, scene_noise_generator(s, pg));
	if (pg->uv)
		fputs(" uv_mapping", out);
	if (pg->bump_size != 0 || pg->accuracy != 0) {
		fnum(out, "bump_size", pg->bump_size);
		fnum(out, "accuracy", pg->accuracy);
	}
	fnum(out, "frequency", pg->frequency);
	fnum(out, "phase", pg->phase);
	static const char *const warps[] = { "turbulence", "repeat", "black_hole", "transform", "planar", "cylindrical",
	                                     "spherical", "toroidal", "cubic" };
	for (const scene_warp *w = pg->warps; w < pg->warps + pg->n_warps; w++) {
		fprintf(out, " %s%s", w->classic ? "classic " : "", warps[w->kind]);
		if (w->kind == WARP_TRANSFORM) {
			for (int i = 0; i < 3; i++) {
				vec(out, "", w->xf.m[i]);
				fputc(' ', out);
				num(out, w->xf.m[i][3]);
			}
			continue;
		}
		const double *v[3] = { w->a, w->b, w->c };
		for (int i = 0; i < 3; i++)
			for (int k = 0; k < 4; k++) {
				fputc(' ', out);
				num(out, v[i][k]);
			}
		if (w->d[0] != 0 || w->d[1] != 0 || w->d[2] != 0)   /* a black hole's turbulence */
			vec(out, "turbulence", w->d);
	}

	fputs(" map", out);
	for (const scene_map_entry *e = pg->map; e < pg->map + pg->n_map; e++) {
		fputs(" [", out);
		num(out, e->value);
		if (textures) {
			fprintf(out, " texture %d]", e->texture);
			continue;
		}
		if (e->pigment >= 0) {
			fprintf(out, " pigment %d]", e->pigment);
			continue;
		}
		for (int k = 0; k < 5; k++) {
			fputc(' ', out);
			num(out, e->colour[k]);
		}
		fputc(']', out);
	}
	fputc('\n', out);
}

/* The pattern pigments and the pool's textures that the objects use. */
static void dump_pigments(FILE *out, const scene *s)
{
	char *used = calloc(s->n_pigments + 1, sizeof *used);
	bool *used_tex = calloc(s->n_textures + 1, sizeof *used_tex);
	if (!used || !used_tex) {
		free(used);
		free(used_tex);
		return;
	}
	for (int i = 0; i < s->n_objects; i++)
		mark_material(s, &s->objects[i].material, used, used_tex);
	for (int m = 0; m < s->n_meshes; m++)
		for (int i = 0; i < s->meshes[m].n_mats; i++)
			mark_material(s, &s->meshes[m].mats[i], used, used_tex);
	for (int i = 0; i < s->n_rainbows; i++)
		mark_pigment(s, s->rainbows[i].pigment, used, used_tex, false);
	for (int i = 0; i < s->n_textures; i++)
		if (used_tex[i]) {
			fprintf(out, "texture %d", i);
			material(out, &s->textures[i]);
			if (!identity(&s->textures[i].tex_xf))
				matrix(out, &s->textures[i].tex_xf);
			fputc('\n', out);
		}
	for (int i = 0; i < s->n_pigments; i++)
		if (used[i])
			dump_pigment(out, s, i, &s->pigments[i], used[i] == 2);
	free(used);
	free(used_tex);
}

static void dump_fog(FILE *out, const scene_fog *f)
{
	fprintf(out, "fog type %d", f->type);
	fnum(out, "distance", f->distance);
	color3(out, "colour", f->colour);
	fnum(out, "filter", f->colour[3]);
	fnum(out, "transmit", f->colour[4]);
	if (f->type == SCENE_FOG_GROUND) {
		fnum(out, "offset", f->offset);
		fnum(out, "alt", f->alt);
		vec(out, "up", f->up);
	}
	if (f->has_turb) {
		vec(out, "turbulence", f->turbulence);
		fprintf(out, " octaves %d", f->octaves);
		fnum(out, "omega", f->omega);
		fnum(out, "lambda", f->lambda);
		fnum(out, "turb_depth", f->turb_depth);
	}
	fputc('\n', out);
}

/* Angles as POV-Ray keeps them: radians, arc and falloff halved. */
static void dump_rainbow(FILE *out, const scene_rainbow *r)
{
	fputs("rainbow", out);
	vec(out, "direction", r->direction);
	vec(out, "up", r->up);
	vec(out, "right", r->right);
	fnum(out, "angle", r->angle);
	fnum(out, "width", r->width);
	fnum(out, "distance", r->distance);
	fnum(out, "jitter", r->jitter);
	fnum(out, "arc_angle", r->arc_angle);
	fnum(out, "falloff_angle", r->falloff_angle);
	fprintf(out, " pigment %d\n", r->pigment);
}

void scene_dump(const scene *s, FILE *out)
{
	const scene_camera *c = &s->camera;
	fputs("camera", out);
	vec(out, "location", c->location);
	vec(out, "direction", c->direction);
	vec(out, "right", c->right);
	vec(out, "up", c->up);
	if (c->type != CAMERA_PERSPECTIVE)
		fprintf(out, " %s", scene_camera_name(c->type));
	if (c->type == CAMERA_SPHERICAL) {
		fnum(out, "angle", c->h_angle);
		fputc(' ', out);
		num(out, c->v_angle);
	} else if (c->type == CAMERA_MESH) {
		fprintf(out, " rays %d distribution %d meshes %d", c->mesh_rays, c->mesh_method, c->mesh_count);
		if (c->mesh_max_distance > 0)
			fnum(out, "max_distance", c->mesh_max_distance);
		if (c->mesh_smooth)
			fputs(" smooth", out);
	} else if (c->type != CAMERA_PERSPECTIVE && c->type != CAMERA_ORTHOGRAPHIC && c->type != CAMERA_OMNIMAX &&
	           c->type != CAMERA_PANORAMIC) {   /* the types whose rays use the angle */
		fnum(out, "angle", c->angle);
	}
	if (c->aperture > 0) {
		fnum(out, "aperture", c->aperture);
		fnum(out, "focal_distance", c->focal_distance);
		fprintf(out, " blur_samples %d", c->blur_samples);
	}
	fputc('\n', out);
	double bg[3] = { s->background[0], s->background[1], s->background[2] };
	fputs("background", out);
	vec(out, "", bg);
	fprintf(out, " max_trace_level %d", s->max_trace_level);
	if (s->has_sky)
		color3(out, "sky", s->sky);
	if (s->assumed_gamma != 0)
		fnum(out, "assumed_gamma", s->assumed_gamma);
	if (s->adc_bailout != 1.0f / 255.0f)
		fnum(out, "adc_bailout", s->adc_bailout);
	if (s->ambient_light[0] != 1 || s->ambient_light[1] != 1 || s->ambient_light[2] != 1)
		color3(out, "ambient_light", s->ambient_light);
	fputc('\n', out);
	for (int i = 0; i < s->n_fogs; i++)
		dump_fog(out, &s->fogs[i]);
	for (int i = 0; i < s->n_rainbows; i++)
		dump_rainbow(out, &s->rainbows[i]);
	for (int i = 0; i < s->n_lights; i++)
		dump_light(out, &s->lights[i]);
	for (int i = 0; i < s->n_objects; i++)
		dump_object(out, &s->objects[i]);
	for (int i = 0; i < s->n_meshes; i++)
		dump_mesh(out, i, &s->meshes[i]);
	for (int i = 0; i < s->n_csgs; i++)
		dump_csg(out, i, &s->csgs[i]);
	dump_pigments(out, s);
}

void scene_object_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	shape_of(o)->bounds(s, o, lo, hi);
}
