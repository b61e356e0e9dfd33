/* shared.h: every struct that crosses the host/device boundary, and nothing else.
 *
 * Included by the host (C11) and prepended to the OpenCL program. Layouts are
 * built from 16-byte groups padded by hand; the host checks each size and offset
 * with _Static_assert (src/lower.c). No float3, bool, size_t or pointers: their
 * sizes differ between host and device. */
#ifndef ECLAT_SHARED_H
#define ECLAT_SHARED_H

#ifndef __OPENCL_VERSION__
typedef unsigned int uint;
/* The host's float4 has the device's size, alignment and member names. */
typedef struct { float x, y, z, w; } __attribute__((aligned(16))) float4;
#endif

/* One node of the binary BVH, 32 bytes (pbrt's LinearBVHNode, tinybvh's layout).
 * Interior node (count == 0): children are nodes[left_first] and nodes[left_first + 1].
 * Leaf (count > 0): primitives prims[left_first .. left_first + count - 1]. */
typedef struct {
	float min_x, min_y, min_z;
	int left_first;
	float max_x, max_y, max_z;
	int count;
} bvh_node;

/* The traversal kernels keep a stack of this many nodes; the host refuses a
 * deeper tree rather than let a ray silently miss. */
#define BVH_STACK_SIZE 64

enum { PRIM_TRIANGLE = 0, PRIM_SPHERE = 1 };

/* A primitive in world space, 64 bytes.
 * Triangle: a = v0, b = v1 - v0, c = v2 - v0 (the Moller-Trumbore edges).
 * Sphere: a.xyz = centre, a.w = radius; b and c unused. */
typedef struct {
	float4 a, b, c;
	int type, material, object, pad;
} dev_prim;

/* A physically based material, 32 bytes, already multiplied out from POV-Ray's
 * pigment and finish: albedo = pigment * diffuse, emission = pigment * emission. */
typedef struct {
	float4 albedo;
	float4 emission;
} dev_material;

/* A point light, 32 bytes: position.xyz and colour.xyz (POV-Ray's light_source). */
typedef struct {
	float4 position;
	float4 color;
} dev_light;

/* Everything a render pass needs besides the buffers, 112 bytes. The camera vectors
 * are POV-Ray's after look_at: a primary ray is direction + sx * right + sy * up
 * with sx, sy in [-0.5, 0.5], sy upwards. */
typedef struct {
	float4 cam_location, cam_direction, cam_right, cam_up;
	float4 background;
	int width, height, max_depth, seed;
	int n_lights, sample_base, samples_per_pass, n_prims;
} dev_params;

#endif
