/* material.cl: scattering. For now the paper's Lambertian surface: BRDF albedo/pi,
 * sampled by cosine so that throughput just takes the albedo. */

/* An orthonormal basis around n without branches on a special axis
 * (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017). */
inline void material_basis(float3 n, float3 *t, float3 *b)
{
	float s = n.z >= 0.0f ? 1.0f : -1.0f;
	float a = -1.0f / (s + n.z);
	float c = n.x * n.y * a;
	*t = (float3)(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
	*b = (float3)(c, s + n.y * n.y * a, -n.y);
}

/* A direction about n with density cos(theta) / pi. */
inline float3 material_sample_cosine(float3 n, float u1, float u2)
{
	float3 t, b;
	material_basis(n, &t, &b);
	float r = sqrt(u1), phi = 2.0f * M_PI_F * u2;
	return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(fmax(0.0f, 1.0f - u1)) * n);
}
