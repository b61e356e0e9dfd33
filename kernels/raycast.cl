/* raycast.cl: one ray per work item, its closest hit and whether anything blocks
 * it, through the renderer's own traversal: what tests/test_traverse.c checks
 * against brute force. rays: two float4 a ray, the origin (w: tmax) and the
 * direction. hits: t, the primitive and instance (as int bits), any hit (0 or 1). */
kernel void raycast(global const bvh_node *nodes, global const dev_prim *prims, int n_prims,
                    int n_planes, global const float4 *rays, global float4 *hits)
{
	int i = get_global_id(0);
	float3 o = rays[2 * i].xyz, d = rays[2 * i + 1].xyz;
	float tmax = rays[2 * i].w;
	uint counts[COUNT_N] = { 0 };
	traverse_hit h = traverse_closest(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts, RAY_CAMERA);
	bool any = traverse_any(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts);
	hits[i] = (float4)(h.t, as_float(h.prim), as_float(h.inst), any ? 1.0f : 0.0f);
}

/* As raycast, and the surface: what tests/test_shapes.c checks against the
 * shapes' own trace() on the host. surfaces: one float4 a ray, the closest
 * hit's geometric normal in world space as the shape gives it (outward, not
 * turned to face the ray); w: its object number (as int bits), -1 for none. */
kernel void raycast_surface(global const bvh_node *nodes, global const dev_prim *prims, global const float4 *normals,
                            int n_prims, int n_planes, global const float4 *rays, global float4 *hits,
                            global float4 *surfaces)
{
	int i = get_global_id(0);
	float3 o = rays[2 * i].xyz, d = rays[2 * i + 1].xyz;
	float tmax = rays[2 * i].w;
	uint counts[COUNT_N] = { 0 };
	traverse_hit h = traverse_closest(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts, RAY_CAMERA);
	bool any = traverse_any(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts);
	hits[i] = (float4)(h.t, as_float(h.prim), as_float(h.inst), any ? 1.0f : 0.0f);
	surfaces[i] = (float4)(0.0f, 0.0f, 0.0f, as_float(-1));
	if (h.prim >= 0) {
		intersect_surface s = intersect_surface_at(0, prims, normals, h.prim, h.inst, h.flip, o + h.t * d);
		surfaces[i] = (float4)(s.ng, as_float(s.object));
	}
}

/* Whether points are inside primitives (shape_inside, POV-Ray's Inside):
 * points[i].xyz the point, w the primitive (as int bits); inside[i] 0 or 1. */
kernel void inside_points(global const dev_prim *prims, global const float4 *points, global int *inside)
{
	int i = get_global_id(0);
	inside[i] = shape_inside(0, prims, &prims[as_int(points[i].w)], points[i].xyz) ? 1 : 0;
}

/* The same, with the surface: each ray's closest hit, the shading normal
 * there (as the shape gives it, not turned to face the ray) and whether the
 * ray's origin is inside the primitive `shape` (its inside test): what
 * tests/test_torus.c checks against the host's trace() and inside test.
 * out: two float4 a ray, (t, the primitive as int bits, any hit, inside) and
 * (the unit normal, 0). */
kernel void shapecast(global const bvh_node *nodes, global const dev_prim *prims, int n_prims, int n_planes,
                      global const float4 *rays, global float4 *out, int shape)
{
	int i = get_global_id(0);
	float3 o = rays[2 * i].xyz, d = rays[2 * i + 1].xyz;
	float tmax = rays[2 * i].w;
	uint counts[COUNT_N] = { 0 };
	traverse_hit h = traverse_closest(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts, RAY_CAMERA);
	bool any = traverse_any(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts);
	bool in = shape_inside(0, prims, &prims[shape], o);
	/* the shading normal, which trace() gives (no smooth triangle here reads
	 * the normals buffer, so the primitives stand in for it) */
	float3 n = h.prim >= 0 && h.inst < 0
	         ? intersect_surface_at(0, prims, (global const float4 *)prims, h.prim, -1, false, o + h.t * d).ns
	         : (float3)(0.0f);
	out[2 * i] = (float4)(h.t, as_float(h.prim), any ? 1.0f : 0.0f, in ? 1.0f : 0.0f);
	out[2 * i + 1] = (float4)(n, 0.0f);
}

/* test_function: the scene's function f at each point, as patterns see it
 * (before a pattern wraps it). */
kernel void function_values(int f, global const float4 *points, global float *out)
{
	int i = get_global_id(0);
	out[i] = scene_function_pattern(0, f, points[i].xyz);   /* no patterns in its functions */
}

/* make bench's traversal-only measure (tests/bench/embree_bench.c, against
 * Embree's rtcIntersect1 and rtcOccluded1): rays as for raycast; hits[i].x the
 * closest hit's distance (INFINITY: none) or, with any, 1 when something
 * blocks the ray and 0 when not. Nothing is shaded. */
kernel void trace_rays(global const bvh_node *nodes, global const dev_prim *prims, int n_prims, int n_planes,
                       global const float4 *rays, global float4 *hits, int any)
{
	int i = get_global_id(0);
	float3 o = rays[2 * i].xyz, d = rays[2 * i + 1].xyz;
	float tmax = rays[2 * i].w;
	uint counts[COUNT_N] = { 0 };
	if (any) {
		hits[i] = (float4)(traverse_any(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts) ? 1.0f : 0.0f);
		return;
	}
	traverse_hit h = traverse_closest(0, nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts, RAY_CAMERA);
	hits[i] = (float4)(h.prim >= 0 ? h.t : INFINITY, as_float(h.prim), as_float(h.inst), 0.0f);
}

/* The pattern and pigment functions a scene calls while it is read
 * (src/device_points.c): at each point, the pattern tree root's value
 * (colour 0: out[2i].x) or its colour (out[2i]: rgb and filter, out[2i+1].x:
 * transmit), exactly as the render's functions evaluate them
 * (function_pattern.cl). Only the pattern buffers hold anything. */
kernel void pattern_points(SCENE_BUFFERS(SCENE_PARAM) global const dev_params *p, int root, int colour,
                           global const float4 *points, global float4 *out)
{
	int i = get_global_id(0);
	uint counts[COUNT_N] = { 0 };
	scene_data sc = { SCENE_BUFFERS(SCENE_FIELD) p, counts };
	float3 q = points[i].xyz;
	out[2 * i + 1] = (float4)(0.0f);
	if (!colour) {
		out[2 * i] = (float4)((float)function_pattern(&sc, root, q.x, q.y, q.z), 0.0f, 0.0f, 0.0f);
		return;
	}
	pigment_colour c = function_pigment_tree(&sc, root, q, (float2)(0.0f), FUNCTION_NO_NORMAL, -FUNCTION_NO_NORMAL);
	out[2 * i] = (float4)(c.rgb, c.filter);
	out[2 * i + 1].x = c.transmit;
}
