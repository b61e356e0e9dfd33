/* scene.c: scene containers, defaults and affine transforms. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

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
	for (int i = 0; i < 3; i++)
		s->ambient_light[i] = 1;
}

static void *grow(void *p, int *cap, size_t size)
{
	*cap = *cap ? 2 * *cap : 16;
	p = realloc(p, *cap * size);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
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

int scene_add_mesh(scene *s, scene_mesh *m)
{
	if (s->n_meshes == s->cap_meshes)
		s->meshes = grow(s->meshes, &s->cap_meshes, sizeof *m);
	s->meshes[s->n_meshes] = *m;
	return s->n_meshes++;
}

static void mesh_free(scene_mesh *m)
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

void scene_free(scene *s)
{
	for (int i = 0; i < s->n_meshes; i++)
		mesh_free(&s->meshes[i]);
	free(s->meshes);
	free(s->objects);
	free(s->lights);
	memset(s, 0, sizeof *s);
}

scene_material scene_default_material(void)
{
	return (scene_material){
		.pigment = { 0, 0, 0, 0, 0 },
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
	};
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
	/* sky parallel to the view: keep the old right, as POV-Ray does */
	if (fabs(r[0]) < 1e-10 && fabs(r[1]) < 1e-10 && fabs(r[2]) < 1e-10)
		memcpy(r, c->right, sizeof r);
	scale_to(r, 1);
	cross(d, r, c->up);
	scale_to(c->up, ul);
	memcpy(c->direction, d, sizeof d);
	scale_to(c->direction, dl);
	memcpy(c->right, r, sizeof r);
	scale_to(c->right, handedness > 0 ? rl : -rl);
	return 0;
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

static void material(FILE *out, const scene_material *m)
{
	fputs(" pigment <", out);
	for (int i = 0; i < 5; i++) {
		num(out, m->pigment[i]);
		fputs(i < 4 ? ", " : ">", out);
	}
	fputs(" diffuse ", out);
	num(out, m->diffuse);
	double e[3] = { m->emission[0], m->emission[1], m->emission[2] };
	vec(out, "emission", e);
}

static void dump_object(FILE *out, const scene_object *o)
{
	fprintf(out, "%s:%d:%d: ", diag_source_name(o->loc.file), o->loc.line, o->loc.col);
	if (o->shape == SHAPE_SPHERE) {
		double c[3], axis[3][3];
		scene_xform_point(&o->xf, o->p[0], c);
		fputs("sphere", out);
		vec(out, "centre", c);
		fputs(" radius ", out);
		num(out, o->radius);
		for (int i = 0; i < 3; i++) {   /* the images of the radius along x, y, z */
			double v[3] = { i == 0 ? o->radius : 0, i == 1 ? o->radius : 0, i == 2 ? o->radius : 0 };
			scene_xform_vector(&o->xf, v, axis[i]);
			vec(out, i == 0 ? "x" : i == 1 ? "y" : "z", axis[i]);
		}
	} else {
		fputs("triangle", out);
		for (int i = 0; i < 3; i++) {
			double w[3];
			scene_xform_point(&o->xf, o->p[i], w);
			vec(out, "", w);
		}
	}
	material(out, &o->material);
	fputc('\n', out);
}

void scene_dump(const scene *s, FILE *out)
{
	const scene_camera *c = &s->camera;
	fputs("camera", out);
	vec(out, "location", c->location);
	vec(out, "direction", c->direction);
	vec(out, "right", c->right);
	vec(out, "up", c->up);
	fputc('\n', out);
	double bg[3] = { s->background[0], s->background[1], s->background[2] };
	fputs("background", out);
	vec(out, "", bg);
	fprintf(out, " max_trace_level %d\n", s->max_trace_level);
	for (int i = 0; i < s->n_lights; i++) {
		const scene_light *l = &s->lights[i];
		double col[3] = { l->color[0], l->color[1], l->color[2] };
		fputs("light_source", out);
		vec(out, "", l->position);
		vec(out, "color", col);
		fputc('\n', out);
	}
	for (int i = 0; i < s->n_objects; i++)
		dump_object(out, &s->objects[i]);
}
