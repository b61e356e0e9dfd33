/* eval_camera_mesh.c: POV-Ray 3.7's mesh_camera, whose rays leave the faces of
 * meshes (texture baking, lens meshes, several views side by side). The
 * meshes go into scene.camera_meshes; lower_camera_mesh.c makes the rays. */
#include <string.h>

#include "eval_int.h"

/* One mesh or mesh2 of the camera: its mesh and placement. */
static int camera_mesh_one(struct eval *e, const ast_node *b, scene_camera *c)
{
	value v;
	if (eval_object(e, b, &v))
		return -1;
	const struct objval *o = v.obj;
	int rc = 0;
	if (o->unsupported || o->n_objs != 1 || o->n_lights || o->objs[0].shape != SHAPE_MESH) {
		eval_error(e, b->loc, "a mesh_camera takes meshes (mesh or mesh2)");
		rc = -1;
	} else {
		scene_camera_mesh m = { o->objs[0].mesh, o->objs[0].xf };
		int at = scene_add_camera_mesh(e->s, &m);
		if (c->mesh_count == 0)
			c->mesh_first = at;
		c->mesh_count++;
	}
	eval_value_free(&v);
	return rc;
}

/* POV-Ray's checks of the numbers, the meshes and smooth, with its words. */
static int camera_mesh_check(struct eval *e, const ast_node *b, scene_camera *c, int n_num,
                             const src_loc loc[3], bool smooth)
{
	if (n_num < 2) {
		eval_error(e, b->loc, "a mesh_camera starts with its rays per pixel and its distribution method");
		return -1;
	}
	if (c->mesh_rays < 1) {
		eval_error(e, loc[0], "a mesh_camera's rays per pixel may not be 0");
		return -1;
	}
	if (c->mesh_method < 0 || c->mesh_method > 3) {
		eval_error(e, loc[1], "unknown mesh_camera distribution method %d: the methods are 0 to 3",
		           c->mesh_method);
		return -1;
	}
	if (c->mesh_method >= 2 && c->mesh_rays != 1) {
		eval_error(e, loc[0], "rays per pixel must be 1 for distribution method %d", c->mesh_method);
		return -1;
	}
	if (n_num == 3 && !(c->mesh_max_distance >= 0)) {
		eval_error(e, loc[2], "a mesh_camera's maximum ray distance may not be negative");
		return -1;
	}
	if (smooth && c->mesh_method != 3) {
		eval_error(e, b->loc, "smooth can only be used with distribution method 3");
		return -1;
	}
	if (c->mesh_count == 0) {
		eval_error(e, b->loc, "a mesh_camera needs a mesh or mesh2");
		return -1;
	}
	if (c->mesh_method == 0 && c->mesh_rays > c->mesh_count) {
		eval_error(e, loc[0], "rays per pixel (%d) must not be more than the meshes (%d) for distribution "
		           "method 0", c->mesh_rays, c->mesh_count);
		return -1;
	}
	if (c->mesh_method == 3 && c->mesh_count > 1)
		eval_warning(e, b->loc, "the meshes after the first are ignored for distribution method 3");
	c->mesh_smooth = smooth;
	return 0;
}

/* mesh_camera { RAYS_PER_PIXEL DISTRIBUTION [MAX_DISTANCE] MESH... [smooth] } */
int eval_camera_mesh(struct eval *e, const ast_node *b, scene_camera *c)
{
	struct cursor cur;
	int err = 0, rc = 0, n_num = 0;
	double num[3] = { 0, 0, 0 };
	src_loc loc[3] = { b->loc, b->loc, b->loc };
	bool smooth = false;
	const ast_node *item;
	c->type = CAMERA_MESH;
	c->mesh_count = 0;
	eval_cursor_init(&cur, e, b);
	while (rc == 0 && (item = eval_next(&cur, &err)) != NULL) {
		if (smooth) {
			rc = eval_not_valid(e, item, "a mesh_camera after smooth");
		} else if (item->kind == AST_IDENT && strcmp(item->str, AST_WORD_SMOOTH) == 0 && !eval_lookup(e, item->str)) {
			smooth = true;
		} else if (item->kind == AST_BLOCK && (item->kw == KW_MESH || item->kw == KW_MESH2)) {
			rc = camera_mesh_one(e, item, c);
		} else if (AST_IS_EXPRESSION(item->kind) && n_num < 3 && c->mesh_count == 0) {
			loc[n_num] = item->loc;
			rc = eval_expect_float(e, item, &num[n_num++]);
		} else {
			rc = eval_not_valid(e, item, "a mesh_camera");
		}
	}
	eval_cursor_free(&cur);
	if (rc || err)
		return -1;
	for (int i = 0; i < n_num && i < 2; i++)
		if (!(num[i] > -1e9 && num[i] < 1e9)) {
			eval_error(e, loc[i], "%g is out of range here", num[i]);
			return -1;
		}
	c->mesh_rays = (int)num[0];   /* POV-Ray's (unsigned int) */
	c->mesh_method = (int)num[1];
	c->mesh_max_distance = num[2];
	return camera_mesh_check(e, b, c, n_num, loc, smooth);
}
