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
	traverse_hit h = traverse_closest(nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts, RAY_CAMERA);
	bool any = traverse_any(nodes, prims, n_prims, n_planes, o, d, 0.0f, tmax, counts);
	hits[i] = (float4)(h.t, as_float(h.prim), as_float(h.inst), any ? 1.0f : 0.0f);
}
