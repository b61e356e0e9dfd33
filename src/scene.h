/* scene.h: the evaluated scene, independent of both the language and the device.
 *
 * Objects keep their object-space geometry and an object-to-world transform; the
 * lowering stage bakes them. Every entity keeps the location of the .scn text that
 * made it, so late errors still point at the source. */
#ifndef ECLAT_SCENE_H
#define ECLAT_SCENE_H

#include <stdbool.h>
#include <stdio.h>
#include "diag.h"

/* An affine transform: world = m * (p, 1), rows of a 3x4 matrix. */
typedef struct {
	double m[3][4];
} xform;

xform scene_xform_identity(void);
xform scene_xform_translate(const double v[3]);
xform scene_xform_scale(const double v[3]);
/* POV-Ray's rotate <a,b,c>: degrees about x, then y, then z, left-handed. */
xform scene_xform_rotate(const double deg[3]);
/* The transform that applies a, then b. */
xform scene_xform_then(const xform *a, const xform *b);
void scene_xform_point(const xform *t, const double p[3], double out[3]);
void scene_xform_vector(const xform *t, const double v[3], double out[3]);

/* A POV-Ray texture reduced to what the renderer uses. */
typedef struct {
	float pigment[5];   /* red, green, blue, filter, transmit; POV-Ray's default is black */
	float diffuse;      /* default 0.6 */
	float ambient[3];   /* default 0.1; not used by the path tracer */
	float emission[3];  /* default 0 */
} scene_material;

typedef enum { SHAPE_SPHERE, SHAPE_TRIANGLE } scene_shape;

typedef struct {
	scene_shape shape;
	double p[3][3];      /* sphere: p[0] is the centre; triangle: the corners (object space) */
	double radius;
	xform xf;            /* object to world */
	scene_material material;
	bool textured;       /* false: takes the texture of an enclosing union, else the default */
	src_loc loc;
} scene_object;

typedef struct {
	double location[3], direction[3], right[3], up[3];  /* final, after look_at */
	src_loc loc;
} scene_camera;

typedef struct {
	double position[3];
	float color[3];
	src_loc loc;
} scene_light;

typedef struct {
	scene_camera camera;
	scene_object *objects;
	int n_objects, cap_objects;
	scene_light *lights;
	int n_lights, cap_lights;
	float background[3];
	int max_trace_level;  /* global_settings; 0 when the scene does not say */
} scene;

void scene_init(scene *s);
/* Appends; exits with a message on out of memory. */
void scene_add_object(scene *s, const scene_object *o);
void scene_add_light(scene *s, const scene_light *l);
void scene_free(scene *s);
/* Writes the scene in world space, one entity a line, for --dump-scene and golden tests. */
void scene_dump(const scene *s, FILE *out);
scene_material scene_default_material(void);
/* POV-Ray's default camera: at the origin looking along +z, 4:3. */
scene_camera scene_default_camera(void);
/* POV-Ray 3.7's look_at: points direction at p keeping the lengths of direction,
 * right and up, orients right and up by sky, keeps the handedness of right.
 * Returns -1 when p is the camera's location. */
int scene_camera_look_at(scene_camera *c, const double p[3], const double sky[3]);

#endif
