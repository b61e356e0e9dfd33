// gen_mesh.cpp: writes the test suite's own large mesh, so that make check needs
// no mesh from outside the repository (issue 13).
//
//   gen_mesh FILE...     each FILE by its extension: .obj, .ply (binary) or .stl (binary)
//
// The mesh is a closed "blob": a latitude-longitude sphere of RINGS bands and
// SEGMENTS sectors, pushed in and out by a sum of sines and stretched, so that it
// has bumps, hollows and parts that hide others, and triangles from slivers at
// the poles to large ones at the equator: 81,280 triangles and 40,642 vertices,
// printed on stdout for the tests to check against. assimp's exporters write
// the files; the tests read them back through eclat's loader (src/mesh_io.c).
#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <cmath>
#include <cstdio>
#include <cstring>

enum { RINGS = 128, SEGMENTS = 320 };

static aiMesh *blob()
{
	const double pi = 3.14159265358979323846;
	aiMesh *m = new aiMesh();
	m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
	m->mNumVertices = (RINGS - 1) * SEGMENTS + 2;
	m->mVertices = new aiVector3D[m->mNumVertices];
	unsigned n = 0;
	// pole 0, then the rings from the top, then pole 1
	for (int i = 0; i <= RINGS; i++)
		for (int j = 0; j < ((i == 0 || i == RINGS) ? 1 : SEGMENTS); j++) {
			double th = pi * i / RINGS, ph = 2 * pi * j / SEGMENTS;
			double x = sin(th) * cos(ph), y = cos(th), z = sin(th) * sin(ph);
			double r = 1 + 0.3 * sin(3 * x + 0.5) * sin(4 * y + 1.3) * sin(5 * z + 2.1) +
			           0.06 * sin(17 * x + 11 * y + 5 * z);
			m->mVertices[n++] = aiVector3D((float)(0.25 + r * x), (float)(1.5 + 1.5 * r * y),
			                               (float)(-0.4 + 0.8 * r * z));
		}
	auto ring = [](int i, int j) { return 1u + (unsigned)((i - 1) * SEGMENTS + j % SEGMENTS); };
	m->mNumFaces = 2 * SEGMENTS * (RINGS - 1);
	m->mFaces = new aiFace[m->mNumFaces];
	unsigned f = 0;
	auto tri = [&](unsigned a, unsigned b, unsigned c) {   // counter-clockwise seen from outside
		aiFace &face = m->mFaces[f++];
		face.mNumIndices = 3;
		face.mIndices = new unsigned[3]{ a, b, c };
	};
	for (int j = 0; j < SEGMENTS; j++) {
		tri(0, ring(1, j + 1), ring(1, j));
		for (int i = 1; i < RINGS - 1; i++) {
			tri(ring(i, j), ring(i, j + 1), ring(i + 1, j));
			tri(ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j));
		}
		tri(n - 1, ring(RINGS - 1, j), ring(RINGS - 1, j + 1));
	}
	return m;
}

int main(int argc, char **argv)
{
	if (argc < 2) {
		fprintf(stderr, "usage: gen_mesh FILE.obj|FILE.ply|FILE.stl...\n");
		return 2;
	}
	aiScene s;   // its destructor frees the mesh, the material and the node
	s.mRootNode = new aiNode("blob");
	s.mRootNode->mNumMeshes = 1;
	s.mRootNode->mMeshes = new unsigned[1]{ 0 };
	s.mNumMeshes = 1;
	s.mMeshes = new aiMesh *[1]{ blob() };
	s.mNumMaterials = 1;   // the exporters expect one
	s.mMaterials = new aiMaterial *[1]{ new aiMaterial() };
	Assimp::Exporter out;
	for (int i = 1; i < argc; i++) {
		const char *ext = strrchr(argv[i], '.');
		const char *format = !ext ? nullptr : !strcmp(ext, ".obj") ? "objnomtl" :
		                     !strcmp(ext, ".ply") ? "plyb" : !strcmp(ext, ".stl") ? "stlb" : nullptr;
		if (!format) {
			fprintf(stderr, "gen_mesh: %s: give a .obj, .ply or .stl file\n", argv[i]);
			return 2;
		}
		if (out.Export(&s, format, argv[i]) != aiReturn_SUCCESS) {
			fprintf(stderr, "gen_mesh: %s: %s\n", argv[i], out.GetErrorString());
			return 1;
		}
	}
	printf("%u triangles, %u vertices\n", s.mMeshes[0]->mNumFaces, s.mMeshes[0]->mNumVertices);
	return 0;
}
