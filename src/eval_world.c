/* eval_world.c: the statements of a scene: camera, light sources, background,
 * sky_sphere, global_settings; the values of blocks and arrays; the words of
 * POV-Ray eclat knows but cannot do. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

/* ---- POV-Ray's words ---- */

/* Words of POV-Ray 3.7 that are not eclat keywords: an object type eclat cannot
 * render, a pattern, or something else (a modifier, a setting). */
const char *eval_pov_word(const char *name)
{
	static const char *const objects[] = {
		"cubic",
		"lathe", "light_group", "ovus",
		"poly", "polygon", "polynomial", "prism", "quadric", "quartic", "sor",
		"text",
	};
	static const char *const patterns[] = {
		"aoi", "average", "image_pattern",
		"pigment_pattern", "slope",
	};
	static const char *const others[] = {
		"albedo", "always_sample", "area_illumination", "brightness", "bump_map", "charset",
		"control0", "control1", "count", "error_bound",
		"exterior", "function", "gray_threshold", "hf_gray_16", "image_map", "interior_texture", "irid",
		"irid_wavelength", "low_error_factor", "material_map", "max_intersections",
		"metric", "minimum_reuse", "mm_per_unit", "nearest_count", "no_radiosity",
		"noise_generator", "pattern", "photons", "pretrace_end", "pretrace_start",
		"projected_through", "quick_color", "quick_colour", "radiosity", "recursion_limit", "slope_map",
		"solid", "spline", "subsurface", "tiles", "warp",
	};
	for (size_t i = 0; i < sizeof objects / sizeof *objects; i++)
		if (strcmp(objects[i], name) == 0)
			return "object";
	for (size_t i = 0; i < sizeof patterns / sizeof *patterns; i++)
		if (strcmp(patterns[i], name) == 0)
			return "pattern";
	for (size_t i = 0; i < sizeof others / sizeof *others; i++)
		if (strcmp(others[i], name) == 0)
			return "other";
	return NULL;
}

/* A POV-Ray word eclat does not have, used as an item (confidence 0.9,
 * variance 0.01...): ignored with one warning, and the values after it with
 * it. 1 when item is no such word. quick_color is ignored without a word:
 * POV-Ray itself uses it only below +Q6, and eclat renders at full quality. */
int eval_skip_pov_word(struct eval *e, struct cursor *c, const ast_node *item)
{
	const ast_node *w = eval_pov_word_item(e, item);
	if (!w)
		return 1;
	if (strcmp(w->str, "quick_color") != 0 && strcmp(w->str, "quick_colour") != 0)
		eval_warn_once(e, w->loc, w->str, "'%s' is not supported yet; ignored", w->str);
	int err = 0;
	if (w == item)   /* its values are the items after it, as far as they go */
		while (eval_next_optional(c, &err))
			;
	return err ? -1 : 0;
}

/* The undeclared POV-Ray word an item starts with, or NULL. The grammar may
 * have made the word and its arguments one expression: "slope -z" is a
 * difference, "quick_colour red 0.7" a colour. */
const ast_node *eval_pov_word_item(struct eval *e, const ast_node *item)
{
	const ast_node *n = item;
	while ((n->kind == AST_BINARY || n->kind == AST_MEMBER || n->kind == AST_INDEX ||
	        (n->kind == AST_COLOR && n->n_kids == 2)) && n->n_kids > 0)
		n = n->kids[0];
	if (n->kind != AST_IDENT || !eval_pov_word(n->str) || eval_lookup(e, n->str))
		return NULL;
	return n;
}

/* The block keyword closest to a misspelt one. */
static const char *near_keyword(const char *name)
{
	static const int blocks[] = {
		KW_BACKGROUND, KW_BOX, KW_CAMERA, KW_FINISH, KW_GLOBAL_SETTINGS, KW_INTERIOR, KW_LIGHT_SOURCE,
		KW_MATERIAL, KW_MESH, KW_NORMAL, KW_OBJECT, KW_PIGMENT, KW_PLANE, KW_SKY_SPHERE, KW_SMOOTH_TRIANGLE,
		KW_SPHERE, KW_TEXTURE, KW_TRIANGLE, KW_UNION, KW_COLOR_MAP, KW_TRANSFORM,
	};
	for (size_t i = 0; i < sizeof blocks / sizeof *blocks; i++) {
		const char *k = ast_keyword_name(blocks[i]);
		size_t lk = strlen(k), ln = strlen(name), same = 0;
		if (lk + 2 < ln || ln + 2 < lk)
			continue;
		for (size_t j = 0; j < ln && j < lk; j++)
			same += name[j] == k[j];
		size_t common = 0;
		while (common < ln && common < lk && name[common] == k[common])
			common++;
		if (common >= 3 && (same + 2 >= lk || same + 2 >= ln))
			return k;
	}
	return NULL;
}

static void unknown_block(struct eval *e, const ast_node *b)
{
	const char *near;
	if (eval_pov_word(b->str))
		eval_error(e, b->loc, "'%s' is not supported yet", b->str);
	else if ((near = near_keyword(b->str)) != NULL)
		eval_error(e, b->loc, "unknown keyword '%s'; did you mean '%s'?", b->str, near);
	else
		eval_error(e, b->loc, "unknown keyword '%s'", b->str);
}

int eval_not_valid(struct eval *e, const ast_node *item, const char *where)
{
	if (item->kind == AST_IDENT && eval_pov_word(item->str) && !eval_lookup(e, item->str))
		eval_error(e, item->loc, "'%s' is not supported yet", item->str);
	else if (AST_IS_EXPRESSION(item->kind))
		eval_error(e, item->loc, "unexpected expression in %s", where);
	else if (item->kind == AST_ENTRY)
		eval_error(e, item->loc, "unexpected map entry [...] in %s", where);
	else if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN)
		unknown_block(e, item);
	else if ((item->kind == AST_ARG || item->kind == AST_FLAG) && ast_keyword_class(item->kw) == KWC_BLOCK)
		eval_error(e, item->loc, "expected '{' after '%s'", ast_keyword_name(item->kw));
	else if (item->kind == AST_FUNCTION || item->kind == AST_ARRAY)
		eval_error(e, item->loc, "unexpected %s in %s", item->kind == AST_FUNCTION ? "function" : "array", where);
	else
		eval_error(e, item->loc, "'%s' is not valid in %s", ast_keyword_name(item->kw), where);
	return -1;
}

/* ---- camera ---- */

struct camera_items {
	scene_camera c;
	double sky[3], look_at[3], angle[2];
	double dir_length;       /* POV-Ray's Direction_Length, the default focal distance */
	bool has_look_at, has_up, has_right, has_focal_point;
	bool declared;           /* it starts from a declared camera, already finished */
	int n_angles;            /* the numbers after angle: 0, 1 or 2 */
	src_loc angle_loc[2];
	xform t;
};

static int camera_vector(struct eval *e, const ast_node *item, struct camera_items *ci)
{
	double *dst;
	switch (item->kw) {
	case KW_LOCATION: dst = ci->c.location; break;
	case KW_DIRECTION: dst = ci->c.direction; break;
	case KW_RIGHT: dst = ci->c.right; ci->has_right = true; break;
	case KW_UP: dst = ci->c.up; ci->has_up = true; break;
	case KW_SKY: dst = ci->sky; break;
	case KW_LOOK_AT: dst = ci->look_at; ci->has_look_at = true; break;
	case KW_FOCAL_POINT: dst = ci->c.focal_point; ci->has_focal_point = true; break;
	default: return 1;
	}
	return eval_expect_vector(e, item->kids[0], dst);
}

/* angle A [, V]: only the spherical camera takes the second number, but the
 * type may come after the angle, so camera_angles checks them at the end. */
static int camera_angle(struct eval *e, struct cursor *c, const ast_node *item, struct camera_items *ci)
{
	int err = 0;
	if (eval_expect_float(e, item->kids[0], &ci->angle[0]))
		return -1;
	ci->angle_loc[0] = item->kids[0]->loc;
	ci->n_angles = 1;
	const ast_node *v = eval_next_optional(c, &err);
	if (v) {
		if (eval_expect_float(e, v, &ci->angle[1]))
			return -1;
		ci->angle_loc[1] = v->loc;
		ci->n_angles = 2;
	}
	return err ? -1 : 0;
}

/* blur_samples N, or blur_samples Min, Max (POV-Ray 3.7): at least Min
 * samples before the stopping rule may end a pixel's. */
static int camera_blur_samples(struct eval *e, struct cursor *c, const ast_node *item, struct camera_items *ci)
{
	double n, most;
	int err = 0;
	if (eval_expect_float(e, item->kids[0], &n))
		return -1;
	const ast_node *second = eval_next_optional(c, &err);
	if (err || (second && eval_expect_float(e, second, &most)))
		return -1;
	if (second && most != 0 && n > most) {
		eval_error(e, second->loc, "blur_samples' minimum %g is larger than its maximum %g", n, most);
		return -1;
	}
	if (!second || most == 0)
		most = n, n = 0;
	ci->c.blur_samples = most < 1 ? 1 : most > 1e6 ? 1000000 : (int)most;
	ci->c.blur_samples_min = n < 0 ? 0 : n > 1e6 ? 1000000 : (int)n;
	return 0;
}

static int camera_float(struct eval *e, struct cursor *c, const ast_node *item, struct camera_items *ci)
{
	double f;
	switch (item->kw) {
	case KW_ANGLE:
		return camera_angle(e, c, item, ci);
	case KW_APERTURE:
		return eval_expect_float(e, item->kids[0], &ci->c.aperture);
	case KW_CONFIDENCE: case KW_VARIANCE:   /* the whitted integrator's stopping rule; as POV-Ray, a bad one warns */
		if (eval_expect_float(e, item->kids[0], &f))
			return -1;
		if (item->kw == KW_CONFIDENCE ? f > 0 && f < 1 : f >= 0 && f <= 1)
			*(item->kw == KW_CONFIDENCE ? &ci->c.confidence : &ci->c.variance) = f;
		else
			eval_warning(e, item->kids[0]->loc, "the camera's %s must be %s, not %g; the default is used",
			          ast_keyword_name(item->kw), item->kw == KW_CONFIDENCE ? "above 0 and below 1" : "from 0 to 1",
			          f);
		return 0;
	case KW_BLUR_SAMPLES:
		return camera_blur_samples(e, c, item, ci);
	default:
		return 1;
	}
}

/* cylinder N, the cylinder camera of type N (1 to 4). */
static int camera_cylinder(struct eval *e, struct cursor *c, const ast_node *item, struct camera_items *ci)
{
	int err = 0;
	double n;
	const ast_node *v = eval_next_optional(c, &err);
	if (err)
		return -1;
	if (!v) {
		eval_error(e, item->loc, "expected the cylinder camera's type (1 to 4) after 'cylinder'");
		return -1;
	}
	if (eval_expect_float(e, v, &n))
		return -1;
	if (eval_int_of(n) < 1 || eval_int_of(n) > 4) {
		eval_error(e, v->loc, "invalid cylinder camera type %g: the types are 1 to 4", n);
		return -1;
	}
	ci->c.type = CAMERA_CYLINDER_1 + (int)n - 1;
	return 0;
}

/* The camera type a flag names, or -1. */
static int camera_type(int kw)
{
	switch (kw) {
	case KW_PERSPECTIVE: return CAMERA_PERSPECTIVE;
	case KW_ORTHOGRAPHIC: return CAMERA_ORTHOGRAPHIC;
	case KW_FISHEYE: return CAMERA_FISHEYE;
	case KW_ULTRA_WIDE_ANGLE: return CAMERA_ULTRA_WIDE_ANGLE;
	case KW_OMNIMAX: return CAMERA_OMNIMAX;
	case KW_PANORAMIC: return CAMERA_PANORAMIC;
	case KW_SPHERICAL: return CAMERA_SPHERICAL;
	default: return -1;
	}
}

static int camera_item(struct eval *e, struct cursor *c, const ast_node *item, struct camera_items *ci, bool first)
{
	int rc = eval_transform_item(e, c, item, &ci->t);
	if (rc != 0)
		return rc < 0 ? -1 : 0;
	if (item->kind == AST_IDENT && strcmp(item->str, "cylinder") == 0 && !eval_lookup(e, item->str))
		return camera_cylinder(e, c, item, ci);
	if ((rc = eval_skip_pov_word(e, c, item)) <= 0)
		return rc;
	if (AST_IS_EXPRESSION(item->kind) && first) {
		value v;
		if (eval_expect_kind(e, item, V_CAMERA, &v))
			return -1;
		ci->c = *v.cam;
		ci->declared = true;
		eval_value_free(&v);
		return 0;
	}
	if (item->kind == AST_FLAG && camera_type(item->kw) >= 0) {
		ci->c.type = camera_type(item->kw);
		return 0;
	}
	if (item->kind == AST_ARG && (rc = camera_vector(e, item, ci)) <= 0)
		return rc;
	if (item->kind == AST_ARG && (rc = camera_float(e, c, item, ci)) <= 0)
		return rc;
	if (item->kind == AST_BLOCK && item->kw == KW_NORMAL) {   /* perturbs the rays (kernels/texture.cl) */
		scene_material m = scene_default_material();
		if (eval_material_block(e, item, &m))
			return -1;
		ci->c.normal = m.normal;
		return 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_MESH_CAMERA) == 0)
		return eval_camera_mesh(e, item, &ci->c);
	return eval_not_valid(e, item, "a camera");
}

/* The angle's numbers, as POV-Ray 3.7 reads them for the camera's type: the
 * perspective and orthographic cameras' set the field of view (below 180
 * degrees; the orthographic camera's may be 0), the spherical camera's are
 * its horizontal and vertical angles (the vertical one half the horizontal
 * unless given), and the other types keep theirs as it is, not negative. */
static int camera_angles(struct eval *e, struct camera_items *ci)
{
	scene_camera *c = &ci->c;
	bool flat = c->type == CAMERA_PERSPECTIVE || c->type == CAMERA_ORTHOGRAPHIC;
	if (ci->n_angles == 0)
		return 0;
	if (ci->n_angles == 2 && c->type != CAMERA_SPHERICAL)
		eval_warn_once(e, ci->angle_loc[1], "vertical angle",
		               "a second camera angle is ignored: only the spherical camera takes one");
	double a = ci->angle[0];
	if (flat && (!(a >= 0 && a < 180) || (a == 0 && c->type == CAMERA_PERSPECTIVE))) {
		eval_error(e, ci->angle_loc[0], "camera angle must be between 0 and 180 degrees");
		return -1;
	}
	for (int i = 0; i < (c->type == CAMERA_SPHERICAL ? ci->n_angles : 1); i++)
		if (!(ci->angle[i] >= 0) || !isfinite(ci->angle[i])) {
			eval_error(e, ci->angle_loc[i], "camera angle must not be negative");
			return -1;
		}
	if (c->type == CAMERA_SPHERICAL) {
		c->h_angle = ci->angle[0];
		c->v_angle = ci->n_angles == 2 ? ci->angle[1] : ci->angle[0] / 2;
	}
	c->angle = ci->angle[0];
	return 0;
}

/* The orthographic camera without up and right, or with an angle, sees what the
 * perspective camera would see in the plane of look_at: right and up grow by
 * |look_at - location| / |direction| (POV-Ray 3.7's parse.cpp; its look_at is
 * <0,0,1> when the camera does not say). */
static void orthographic_area(struct camera_items *ci)
{
	scene_camera *c = &ci->c;
	if (c->type != CAMERA_ORTHOGRAPHIC || ((ci->has_up || ci->has_right) && ci->n_angles == 0))
		return;
	if (ci->declared && !ci->has_look_at && ci->n_angles == 0)
		return;   /* a declared camera's area is made: camera { C } must not grow it again */
	double at[3] = { 0, 0, 1 }, k1 = 0, k2 = 0;
	if (ci->has_look_at)
		memcpy(at, ci->look_at, sizeof at);
	for (int k = 0; k < 3; k++) {
		k1 += (at[k] - c->location[k]) * (at[k] - c->location[k]);
		k2 += c->direction[k] * c->direction[k];
	}
	k1 = sqrt(k1);
	k2 = sqrt(k2);
	if (k1 <= 1e-10 || k2 <= 1e-10)
		return;
	for (int k = 0; k < 3; k++) {
		c->right[k] *= k1 / k2;
		c->up[k] *= k1 / k2;
	}
}

static double length3(const double v[3])
{
	return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* The types that bend their rays use direction, right and up as unit axes (and
 * the lengths of right and up as the image's proportions): none may be 0. */
static int camera_axes(struct eval *e, const ast_node *b, const scene_camera *c)
{
	if (c->type == CAMERA_PERSPECTIVE || c->type == CAMERA_ORTHOGRAPHIC || c->type == CAMERA_PANORAMIC)
		return 0;
	if (length3(c->direction) > 0 && length3(c->right) > 0 && length3(c->up) > 0)
		return 0;
	eval_error(e, b->loc, "the %s camera needs direction, right and up vectors that are not 0",
	           scene_camera_name(c->type));
	return -1;
}

/* The focal distance as POV-Ray 3.7 sets it (parse.cpp), before the
 * transformations: a copied camera keeps its own unless focal_point is given. */
static void camera_focus(struct camera_items *ci)
{
	scene_camera *c = &ci->c;
	if (ci->has_focal_point) {
		double d[3] = { c->focal_point[0] - c->location[0], c->focal_point[1] - c->location[1],
		                c->focal_point[2] - c->location[2] };
		c->focal_distance = length3(d);
	} else if (c->focal_distance < 0) {
		c->focal_distance = ci->dir_length;
	}
	if (c->focal_distance == 0)
		c->focal_distance = 1;
}

/* POV-Ray 3.7's order, whatever the order in the file: the vectors, then angle,
 * then look_at, then the orthographic camera's area, then the transformations. */
static int camera_finish(struct eval *e, const ast_node *b, struct camera_items *ci)
{
	scene_camera *c = &ci->c;
	if (camera_angles(e, ci))
		return -1;
	if ((c->type == CAMERA_PERSPECTIVE || c->type == CAMERA_ORTHOGRAPHIC) && ci->n_angles > 0 &&
	    ci->angle[0] > 0) {
		double dl = sqrt(c->direction[0] * c->direction[0] + c->direction[1] * c->direction[1] +
		                 c->direction[2] * c->direction[2]);
		double rl = sqrt(c->right[0] * c->right[0] + c->right[1] * c->right[1] + c->right[2] * c->right[2]);
		double want = rl / tan(ci->angle[0] * M_PI / 360.0) / 2.0;
		for (int k = 0; k < 3 && dl > 0; k++)
			c->direction[k] *= want / dl;
		ci->dir_length = want;
	}
	if (ci->has_look_at)
		ci->dir_length = length3(c->direction);
	int look = ci->has_look_at ? scene_camera_look_at(c, ci->look_at, ci->sky) : 0;
	if (look < 0) {
		eval_error(e, b->loc, "camera location and look_at point must be different");
		return -1;
	}
	orthographic_area(ci);
	camera_focus(ci);
	if (look > 0)
		eval_warning(e, b->loc, "the camera looks along its sky vector; keeping the right vector, as POV-Ray "
		             "does (give another sky)");
	scene_xform_point(&ci->t, c->location, c->location);
	scene_xform_vector(&ci->t, c->direction, c->direction);
	scene_xform_vector(&ci->t, c->right, c->right);
	scene_xform_vector(&ci->t, c->up, c->up);
	return camera_axes(e, b, c);
}

/* camera { [CAMERA_IDENTIFIER] [perspective | orthographic | fisheye | ultra_wide_angle | omnimax |
 *          panoramic | cylinder N | spherical] [location <L>] [direction <D>] [right <R>]
 *          [up <U>] [sky <S>] [angle A [, V]] [look_at <P>] [aperture F] [focal_point <P>]
 *          [blur_samples N] [TRANSFORMATIONS...] } */
int eval_camera(struct eval *e, const ast_node *b, scene_camera *out)
{
	struct camera_items ci = { .c = scene_default_camera(), .sky = { 0, 1, 0 }, .dir_length = 1,
	                           .t = scene_xform_identity() };
	ci.c.loc = b->loc;
	ci.c.blur_samples = 0;
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		rc = camera_item(e, &c, item, &ci, first);
		first = false;
	}
	eval_cursor_free(&c);
	if (rc || err || camera_finish(e, b, &ci))
		return -1;
	*out = ci.c;
	return 0;
}

/* ---- light sources ---- */

/* light_source { LIGHT_IDENTIFIER ...}: a declared light, to change. 1 if not. */
static int light_identifier(struct eval *e, const ast_node *pos, struct lightval *l)
{
	if (pos->kind != AST_IDENT)
		return 1;
	const value *v = eval_lookup(e, pos->str);
	if (!v || v->kind != V_OBJECT)
		return 1;
	if (v->obj->n_lights != 1 || v->obj->n_objs) {
		eval_error(e, pos->loc, "'%s' is not a light_source", pos->str);
		return -1;
	}
	*l = v->obj->lights[0];
	l->looks = l->n_looks ? eval_xrealloc(NULL, l->n_looks * sizeof *l->looks) : NULL;
	if (l->n_looks)
		memcpy(l->looks, v->obj->lights[0].looks, l->n_looks * sizeof *l->looks);
	return 0;
}

static int light_args(struct eval *e, struct cursor *c, const ast_node *b, struct lightval *l)
{
	int err = 0;
	double col[5];
	const ast_node *pos = eval_next_expr(c, &err);
	int rc = pos ? light_identifier(e, pos, l) : 1;
	if (rc <= 0)
		return rc;
	const ast_node *color = pos ? eval_next_expr(c, &err) : NULL;
	if (!color) {
		if (!err)
			eval_error(e, b->loc, "light_source needs a location and a colour");
		return -1;
	}
	if (eval_expect_vector(e, pos, l->light.position) || eval_expect_color(e, color, col))
		return -1;
	for (int i = 0; i < 3; i++)
		l->light.color[i] = (float)col[i];
	return 0;
}

/* area_light <Axis1>, <Axis2>, Size1, Size2 */
static int area_light(struct eval *e, struct cursor *c, const ast_node *item, scene_light *l)
{
	int err = 0;
	const ast_node *a2 = eval_next_expr(c, &err), *s1 = a2 ? eval_next_expr(c, &err) : NULL,
	               *s2 = s1 ? eval_next_expr(c, &err) : NULL;
	if (!s2) {
		if (!err)
			eval_error(e, item->loc, "area_light needs <Axis1>, <Axis2>, Size1, Size2");
		return -1;
	}
	double f1, f2;
	if (eval_expect_vector(e, item->kids[0], l->axis1) || eval_expect_vector(e, a2, l->axis2) ||
	    eval_expect_float(e, s1, &f1) || eval_expect_float(e, s2, &f2))
		return -1;
	if (f1 < 1 || f2 < 1 || f1 > 1e4 || f2 > 1e4) {
		eval_error(e, f1 < 1 || f1 > 1e4 ? s1->loc : s2->loc, "an area_light has 1 to 10000 lights along each axis");
		return -1;
	}
	l->area = true;
	l->size1 = (int)f1;
	l->size2 = (int)f2;
	return 0;
}

static int light_arg(struct eval *e, struct cursor *c, const ast_node *item, scene_light *l)
{
	double f;
	switch (item->kw) {
	case KW_POINT_AT: return eval_expect_vector(e, item->kids[0], l->point_at);
	case KW_AREA_LIGHT: return area_light(e, c, item, l);
	case KW_ADAPTIVE:
		if (eval_expect_float(e, item->kids[0], &f))
			return -1;
		l->adaptive = f < 0 ? 0 : f > 100 ? 100 : (int)f;
		return 0;
	case KW_RADIUS: case KW_FALLOFF: case KW_TIGHTNESS: case KW_FADE_DISTANCE: case KW_FADE_POWER:
		if (eval_expect_float(e, item->kids[0], &f))
			return -1;
		*(item->kw == KW_RADIUS ? &l->radius : item->kw == KW_FALLOFF ? &l->falloff
		  : item->kw == KW_TIGHTNESS ? &l->tightness : item->kw == KW_FADE_DISTANCE ? &l->fade_distance
		  : &l->fade_power) = (float)f;
		return 0;
	default:
		return 1;
	}
}

static int light_flag(struct eval *e, const ast_node *item, scene_light *l)
{
	switch (item->kw) {
	case KW_SPOTLIGHT: l->kind = LIGHT_SPOT; return 0;
	case KW_PARALLEL:
		if (l->kind == LIGHT_SPOT)
			eval_warn_once(e, item->loc, "parallel spotlight", "a parallel spotlight is not supported yet; "
			               "it stays a spotlight");
		else
			l->kind = LIGHT_PARALLEL;
		return 0;
	case KW_JITTER: l->jitter = true; return 0;
	case KW_CIRCULAR: l->circular = true; return 0;
	case KW_ORIENT: l->orient = true; return 0;
	case KW_SHADOWLESS: l->shadowless = true; return 0;
	default: return 1;
	}
}

/* media_attenuation [Bool], media_interaction [Bool] */
static int media_attenuation(struct eval *e, struct cursor *c, const ast_node *item, scene_light *l)
{
	int err = 0;
	double on = 1;
	const ast_node *arg = eval_next_optional(c, &err);
	if (err || (arg && eval_expect_float(e, arg, &on)))
		return -1;
	if (item->kw == KW_MEDIA_INTERACTION)
		l->no_media_interaction = !eval_truth(on);
	else
		l->media_attenuation = eval_truth(on);
	return 0;
}

static int light_item(struct eval *e, struct cursor *c, const ast_node *item, struct lightval *l)
{
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, c, item, &t);
	if (rc > 0)
		eval_transform_light(l, &t);
	if (rc != 0)
		return rc < 0 ? -1 : 0;
	if (item->kind == AST_ARG && (rc = light_arg(e, c, item, &l->light)) <= 0)
		return rc;
	if (item->kind == AST_FLAG && (rc = light_flag(e, item, &l->light)) <= 0)
		return rc;
	if (item->kind == AST_FLAG && (item->kw == KW_MEDIA_ATTENUATION || item->kw == KW_MEDIA_INTERACTION))
		return media_attenuation(e, c, item, &l->light);
	if (item->kind == AST_BLOCK && item->kw == KW_LOOKS_LIKE)
		return eval_looks_like(e, item, l->light.position, l);
	if ((rc = eval_skip_pov_word(e, c, item)) <= 0)
		return rc;
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str) &&
	    strcmp(eval_pov_word(item->str), "object") != 0) {
		eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
		return 0;
	}
	return eval_not_valid(e, item, "a light_source");
}

/* light_source { <Location>, COLOR [spotlight] [parallel] [point_at <P>] [radius F]
 *   [falloff F] [tightness F] [area_light <A1>, <A2>, N1, N2] [adaptive N] [jitter]
 *   [circular] [orient] [shadowless] [media_attenuation [Bool]] [media_interaction [Bool]]
 *   [fade_distance F] [fade_power F]
 *   [looks_like { OBJECT }] [TRANSFORMATIONS...] } */
int eval_light(struct eval *e, const ast_node *b, value *out)
{
	struct lightval l = { .light = scene_default_light() };
	l.light.loc = b->loc;
	struct cursor c;
	int err = 0, rc;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	rc = light_args(e, &c, b, &l);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = light_item(e, &c, item, &l);
	eval_cursor_free(&c);
	if (rc == 0 && !err && l.light.circular && l.light.area && (l.light.size1 <= 1 || l.light.size2 <= 1)) {
		eval_error(e, b->loc, "a circular area_light needs more than 1 light along each axis");
		rc = -1;
	}
	if (rc || err) {
		free(l.looks);
		return -1;
	}
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	eval_objval_add_light(out->obj, &l);
	return 0;
}

/* ---- background, sky_sphere, global_settings ---- */

/* background { COLOR } */
static int background(struct eval *e, const ast_node *b)
{
	struct cursor c;
	int err = 0, rc = 0;
	double col[5];
	eval_cursor_init(&c, e, b);
	const ast_node *item = eval_next(&c, &err), *more = NULL;
	if (!item || !AST_IS_EXPRESSION(item->kind)) {
		if (!err)
			eval_error(e, item ? item->loc : b->loc, "background needs one colour");
		rc = -1;
	} else if ((rc = eval_expect_color(e, item, col)) == 0 && (more = eval_next(&c, &err)) != NULL) {
		rc = eval_not_valid(e, more, "a background");
	}
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	for (int i = 0; i < 3; i++)
		e->s->background[i] = (float)col[i];
	int old = e->version < 3.7;   /* POV-Ray's parser: transparent for older scenes */
	e->s->background_ft[0] = old ? 0.0f : (float)col[3];
	e->s->background_ft[1] = old ? 1.0f : (float)col[4];
	return 0;
}

/* sky_sphere { [SKY_SPHERE_IDENTIFIER] [PIGMENT...] [emission COLOR]
 *              [TRANSFORMATION...] }: its layers go to the scene (sky_layers).
 * Its value keeps them too, in the pool scene.textures (v[0] the first, v[1]
 * how many): an include file declares several skies, and a scene's
 * sky_sphere { S } takes S's layers, not the last declared's. */
static int sky_sphere(struct eval *e, const ast_node *b, value *out)
{
	struct cursor c;
	int err = 0, rc = 0, pigments = 0;
	scene *s = e->s;
	scene_material m = e->default_mat, *layers = NULL;
	xform sky_xf = scene_xform_identity();
	float emission[3] = { 1, 1, 1 };
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		xform t = scene_xform_identity();
		value v;
		if (AST_IS_EXPRESSION(item->kind) && pigments == 0) {
			if ((rc = eval_expr(e, item, &v)) == 0 && (v.kind != V_OTHER || strcmp(v.str, "sky_sphere") != 0))
				rc = eval_not_valid(e, item, "a sky_sphere");
			else if (rc == 0 && v.v[1] > 0) {   /* the declared sky's layers, then this one's */
				pigments = (int)v.v[1];
				layers = eval_xrealloc(NULL, pigments * sizeof *layers);
				memcpy(layers, &s->textures[(int)v.v[0]], pigments * sizeof *layers);
				sky_xf = layers[0].tex_xf;
				memcpy(emission, layers[0].emission, sizeof emission);
			}
			eval_value_free(&v);
		} else if (item->kind == AST_BLOCK && item->kw == KW_PIGMENT) {
			m = e->default_mat;
			rc = eval_material_block(e, item, &m);
			if (rc == 0) {
				layers = eval_xrealloc(layers, (pigments + 1) * sizeof *layers);
				layers[pigments++] = m;
			}
		} else if (item->kind == AST_ARG && item->kw == KW_EMISSION) {
			double col[5];
			rc = eval_expect_color(e, item->kids[0], col);
			for (int i = 0; i < 3; i++)
				emission[i] = (float)col[i];
		} else if ((rc = eval_transform_item(e, &c, item, &t)) == 0) {
			rc = eval_not_valid(e, item, "a sky_sphere");
		} else {
			if (rc > 0)   /* they turn the sky's patterns */
				sky_xf = scene_xform_then(&sky_xf, &t);
			rc = rc < 0 ? -1 : 0;
		}
	}
	eval_cursor_free(&c);
	if (rc || err) {
		free(layers);
		return -1;
	}
	free(s->sky_layers);   /* the last sky_sphere evaluated holds the scene's layers */
	s->sky_layers = layers;
	s->n_sky_layers = pigments;
	for (int i = 0; i < pigments; i++) {
		s->sky_layers[i].tex_xf = sky_xf;
		memcpy(s->sky_layers[i].emission, emission, sizeof emission);
	}
	int first = s->n_textures;
	for (int i = 0; i < pigments; i++)
		scene_add_texture(s, &s->sky_layers[i]);
	if (pigments)
		m = s->sky_layers[pigments - 1];
	*out = (value){ .kind = V_OTHER, .str = eval_xstrdup("sky_sphere"), .mat = m, .v = { first, pigments } };
	return 0;
}

static int global_arg(struct eval *e, const ast_node *item)
{
	double f;
	float *c3 = NULL;
	switch (item->kw) {
	case KW_ASSUMED_GAMMA: case KW_ADC_BAILOUT: case KW_MAX_TRACE_LEVEL:
		if (eval_expect_float(e, item->kids[0], &f))
			return -1;
		break;
	case KW_AMBIENT_LIGHT:
		c3 = e->s->ambient_light;
		break;
	default:
		return eval_not_valid(e, item, "global_settings");
	}
	if (c3) {
		double col[5];
		if (eval_expect_color(e, item->kids[0], col))
			return -1;
		for (int i = 0; i < 3; i++)
			c3[i] = (float)col[i];
		return 0;
	}
	if (item->kw == KW_MAX_TRACE_LEVEL && (f < 1 || f > 256)) {
		eval_error(e, item->kids[0]->loc, "max_trace_level must be between 1 and 256");
		return -1;
	}
	if (item->kw == KW_ASSUMED_GAMMA && f <= 0) {
		eval_error(e, item->kids[0]->loc, "assumed_gamma must be greater than 0");
		return -1;
	}
	if (item->kw == KW_MAX_TRACE_LEVEL)
		e->s->max_trace_level = (int)f;
	else if (item->kw == KW_ASSUMED_GAMMA)
		e->s->assumed_gamma = (float)f;
	else
		e->s->adc_bailout = (float)f;
	return 0;
}

/* charset ascii | utf8 | sys: eclat reads every string as UTF-8, which
 * covers ASCII; 1 when item is not charset. */
static int charset(struct eval *e, struct cursor *c, const ast_node *item)
{
	if (item->kind != AST_IDENT || strcmp(item->str, AST_WORD_CHARSET) != 0 || eval_lookup(e, item->str))
		return 1;
	int err = 0;
	const ast_node *set = eval_next(c, &err);
	if (err)
		return -1;
	if (!set || set->kind != AST_IDENT ||
	    (strcmp(set->str, "ascii") != 0 && strcmp(set->str, "utf8") != 0 && strcmp(set->str, "sys") != 0)) {
		eval_error(e, set ? set->loc : item->loc, "charset is ascii, utf8 or sys");
		return -1;
	}
	if (strcmp(set->str, "sys") == 0)
		eval_warn_once(e, set->loc, "charset sys", "charset sys is read as utf8");
	return 0;
}

/* noise_generator N: the generator of the patterns that name none. 1 when
 * item is something else. */
static int noise_generator(struct eval *e, struct cursor *c, const ast_node *item)
{
	if (item->kind != AST_IDENT || strcmp(item->str, AST_WORD_NOISE_GENERATOR) != 0 || eval_lookup(e, item->str))
		return 1;
	int err = 0;
	double g;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, item->loc, "'noise_generator' needs a value");
		return -1;
	}
	if (eval_expect_float(e, arg, &g))
		return -1;
	if (g < 1 || g >= 4) {
		eval_error(e, arg->loc, "noise_generator is 1, 2 or 3");
		return -1;
	}
	e->s->noise_generator = (int)g;
	e->noise_given = true;
	return 0;
}

/* number_of_waves N: the wave sources of every waves and ripples pattern,
 * whichever global_settings says it (POV-Ray reads the setting when it
 * renders). POV-Ray takes 1 for N below 1, with a warning; eclat also refuses
 * more than a million, which would stall a kernel on every pattern point. */
static int number_of_waves(struct eval *e, struct cursor *c, const ast_node *item)
{
	if (item->kind != AST_IDENT || strcmp(item->str, AST_WORD_NUMBER_OF_WAVES) != 0 || eval_lookup(e, item->str))
		return 1;
	int err = 0;
	double n;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, item->loc, "'number_of_waves' needs a value");
		return -1;
	}
	if (eval_expect_float(e, arg, &n))
		return -1;
	if (n >= 1e6 + 1) {
		eval_error(e, arg->loc, "number_of_waves %g is more than eclat takes (1000000)", n);
		return -1;
	}
	if (!(n >= 1)) {   /* POV-Ray's (int) cast: 0.5 is 0 too */
		eval_warning(e, arg->loc, "number_of_waves must be greater than 0; changed to 1 (as POV-Ray does)");
		n = 1;
	}
	e->s->number_of_waves = (int)n;
	return 0;
}

/* global_settings { [assumed_gamma F] [max_trace_level N] [adc_bailout F]
 *                   [ambient_light COLOR] [noise_generator N] [number_of_waves N] }: POV-Ray's other
 * settings are ignored. */
static int global_settings(struct eval *e, const ast_node *b)
{
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if ((rc = charset(e, &c, item)) <= 0 || (rc = noise_generator(e, &c, item)) <= 0 ||
		    (rc = number_of_waves(e, &c, item)) <= 0 ||
		    (rc = eval_irid_wavelength(e, &c, item)) <= 0)
			continue;
		if ((rc = eval_skip_pov_word(e, &c, item)) <= 0)
			continue;
		if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str)) {
			eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
			rc = 0;
		} else if (item->kind == AST_ARG) {
			rc = global_arg(e, item);
		} else {
			rc = eval_not_valid(e, item, "global_settings");
		}
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

/* ---- values of blocks and arrays ---- */

static int array_init(struct eval *e, const ast_node *init, struct array *a, int dim, int *at)
{
	if (init->n_kids != a->size[dim]) {
		eval_error(e, init->loc, "the initialiser has %d element%s, the array's dimension %d has %d", init->n_kids,
		           init->n_kids == 1 ? "" : "s", dim + 1, a->size[dim]);
		return -1;
	}
	for (int i = 0; i < init->n_kids; i++) {
		const ast_node *k = init->kids[i];
		if (dim + 1 < a->dims) {
			if (k->kind != AST_INIT) {
				eval_error(e, k->loc, "expected { ... } for dimension %d", dim + 2);
				return -1;
			}
			if (array_init(e, k, a, dim + 1, at))
				return -1;
			continue;
		}
		if (k->kind == AST_INIT) {
			eval_error(e, k->loc, "the array has %d dimension%s", a->dims, a->dims == 1 ? "" : "s");
			return -1;
		}
		value *v = &a->elems[(*at)++];
		if (AST_IS_EXPRESSION(k->kind) ? eval_expr(e, k, v) : eval_block_value(e, k, v))
			return -1;
	}
	return 0;
}

#define MAX_ARRAY_ELEMENTS 4000000   /* a value is some 300 bytes */

/* array[N1][N2]... [{ INITIALISERS }] */
static int array(struct eval *e, const ast_node *n, value *out)
{
	const ast_node *dims = n->kids[0];
	struct array a = { .dims = dims->n_kids, .n = 1 };
	if (a.dims > 5) {
		eval_error(e, n->loc, "an array has at most 5 dimensions");
		return -1;
	}
	for (int i = 0; i < a.dims; i++) {
		if (eval_expect_int(e, dims->kids[i], &a.size[i]))
			return -1;
		if (a.size[i] < 1) {
			eval_error(e, dims->kids[i]->loc, "an array dimension must be at least 1, not %d", a.size[i]);
			return -1;
		}
		if (a.size[i] > MAX_ARRAY_ELEMENTS / a.n) {
			eval_error(e, dims->kids[i]->loc, "this array would have more than %d elements", MAX_ARRAY_ELEMENTS);
			return -1;
		}
		a.n *= a.size[i];
	}
	a.elems = calloc(a.n, sizeof *a.elems);
	if (!a.elems)
		eval_xrealloc(NULL, (size_t)-1 / 2);
	*out = (value){ .kind = V_ARRAY, .arr = eval_xrealloc(NULL, sizeof a) };
	*out->arr = a;
	int at = 0;
	if (n->n_kids > 1 && array_init(e, n->kids[1], out->arr, 0, &at)) {
		eval_value_free(out);
		return -1;
	}
	return 0;
}

static int transform_value(struct eval *e, const ast_node *b, value *out)
{
	*out = (value){ .kind = V_TRANSFORM, .xf = scene_xform_identity() };
	ast_node item = { .kind = AST_BLOCK, .kw = KW_TRANSFORM, .loc = b->loc, .kids = b->kids, .n_kids = b->n_kids };
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, NULL, &item, &t);
	out->xf = t;
	return rc < 0 ? -1 : 0;
}

int eval_block_value(struct eval *e, const ast_node *b, value *out)
{
	*out = (value){ .kind = V_NONE };
	if (b->kind == AST_FUNCTION) {
		*out = (value){ .kind = V_FUNCTION, .node = b, .env = eval_capture(e, b) };
		return eval_function_pattern_body(b) ? eval_function_pigment(e, b, &out->mat) : 0;
	}
	if (b->kind == AST_ARRAY)
		return array(e, b, out);
	if (b->kind != AST_BLOCK)
		return eval_not_valid(e, b, "a value");
	if (eval_is_object_block(b))
		return eval_object(e, b, out);
	switch (b->kw) {
	case KW_PIGMENT: case KW_FINISH: case KW_TEXTURE: case KW_NORMAL: case KW_INTERIOR: case KW_MATERIAL:
	case KW_COLOR_MAP: case KW_COLOUR_MAP: case KW_PIGMENT_MAP: case KW_TEXTURE_MAP: case KW_NORMAL_MAP:
		return eval_material_value(e, b, out);
	case KW_TRANSFORM:
		return transform_value(e, b, out);
	case KW_CAMERA: {
		scene_camera c;
		if (eval_camera(e, b, &c))
			return -1;
		*out = (value){ .kind = V_CAMERA, .cam = eval_xrealloc(NULL, sizeof c) };
		*out->cam = c;
		return 0;
	}
	case KW_SKY_SPHERE:
		return sky_sphere(e, b, out);
	case KW_FOG:
		return eval_fog_value(e, b, out);
	case KW_RAINBOW:   /* POV-Ray 3.7 draws a declared rainbow wrong and then crashes */
		eval_error(e, b->loc, "a rainbow cannot be declared: POV-Ray 3.7 converts a declared rainbow's "
		           "angles a second time where it is used; write the rainbow where it is used");
		return -1;
	case KW_MEDIA:
		return eval_media_value(e, b, out);
	case KW_DENSITY:
		return eval_density_value(e, b, out);
	case KW_UNKNOWN:
		if (strcmp(b->str, "layers") == 0)
			return eval_material_value(e, b, out);
		if (strcmp(b->str, AST_WORD_SPLINE) == 0)
			return eval_spline_value(e, b, out);
		if (eval_pov_word(b->str)) {   /* declared, for a use eclat will refuse */
			*out = (value){ .kind = V_OTHER, .str = eval_xstrdup(b->str) };
			return 0;
		}
		return eval_not_valid(e, b, "a #declare");
	default:
		eval_error(e, b->loc, "%s cannot be declared", ast_keyword_name(b->kw));
		return -1;
	}
}

/* ---- statements ---- */

static int place_object(struct eval *e, const ast_node *b)
{
	value v;
	if (eval_object(e, b, &v))
		return -1;
	eval_place(e, &v);
	eval_value_free(&v);
	return 0;
}

static int statement_block(struct eval *e, const ast_node *b)
{
	value v;
	switch (b->kw) {
	case KW_CAMERA: return eval_camera(e, b, &e->s->camera);
	case KW_BACKGROUND: return background(e, b);
	case KW_GLOBAL_SETTINGS: return global_settings(e, b);
	case KW_FOG: return eval_fog_statement(e, b);
	case KW_RAINBOW: return eval_rainbow_statement(e, b);
	case KW_MEDIA: return eval_media_statement(e, b);
	case KW_SKY_SPHERE:
		if (sky_sphere(e, b, &v))
			return -1;
		e->s->has_sky = true;
		for (int i = 0; i < 3; i++)
			e->s->sky[i] = v.mat.pigment[i];
		eval_value_free(&v);
		return 0;
	default:
		break;
	}
	if (eval_is_object_block(b))
		return place_object(e, b);
	if (b->kw == KW_UNKNOWN && strcmp(b->str, "default") == 0)
		return eval_default(e, b);   /* POV-Ray still reads the old "default { }" */
	if (b->kw == KW_UNKNOWN && eval_pov_word(b->str)) {
		eval_warn_once(e, b->loc, b->str, "'%s' is not supported yet; ignored", b->str);
		return 0;
	}
	return eval_not_valid(e, b, "the scene (expected an object, camera, light_source or directive)");
}

int eval_scene_statement(struct eval *e, const ast_node *item)
{
	if (item->kind == AST_BLOCK)
		return statement_block(e, item);
	if (item->kind == AST_CALL) {   /* not a macro: say why */
		value v;
		if (eval_expr(e, item, &v))
			return -1;
		eval_value_free(&v);
	}
	return eval_not_valid(e, item, "the scene (expected an object, camera, light_source or directive)");
}
