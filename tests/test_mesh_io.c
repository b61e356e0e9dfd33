/* test_mesh_io.c: mesh files through assimp.
 *
 *   test_mesh_io TMP_DIR [FILE=TRIANGLES]...
 *
 * Each FILE must load with TRIANGLES triangles (tests/mesh_io.test names the
 * meshes: its own, assimp's test models and the optional larger ones); TMP_DIR
 * gets small files written here. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_io.h"
#include "mesh_arg.h"

static int failures;

static void check(int ok, const char *what)
{
	printf("%s: %s\n", ok ? "ok" : "FAIL", what);
	failures += !ok;
}

static void free_mesh(scene_mesh *m)
{
	free(m->v);
	free(m->nrm);
	free(m->face);
	free(m->face_nrm);
}

/* Loads path and checks its triangle count and that every index is in range. */
static void expect_triangles(const char *path, int want)
{
	scene_mesh m;
	char err[512], what[1024];
	if (mesh_io_load(path, MESH_IO_DEFAULT_TIME_LIMIT, 0, &m, err, sizeof err) != 0) {
		snprintf(what, sizeof what, "%s loads (%s)", path, err);
		check(0, what);
		return;
	}
	int in_range = 1;
	for (int f = 0; f < m.n_faces; f++)
		for (int k = 0; k < 3; k++)
			in_range &= m.face[f][k] >= 0 && m.face[f][k] < m.n_v;
	snprintf(what, sizeof what, "%s: %d triangles (expected %d), %d vertices, indices in range",
	         path, m.n_faces, want, m.n_v);
	check(m.n_faces == want && in_range, what);
	free_mesh(&m);
}

static void expect_error(const char *path, const char *label)
{
	scene_mesh m;
	char err[512], what[1024];
	int rc = mesh_io_load(path, MESH_IO_DEFAULT_TIME_LIMIT, 0, &m, err, sizeof err);
	snprintf(what, sizeof what, "%s is refused with a reason (%s)", label, rc ? err : "loaded");
	check(rc != 0 && err[0], what);
	if (rc == 0)
		free_mesh(&m);
}

static void write_file(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	if (f) {
		fputs(text, f);
		fclose(f);
	}
}

int main(int argc, char **argv)
{
	if (argc < 2) {
		fprintf(stderr, "usage: test_mesh_io TMP_DIR [FILE=TRIANGLES]...\n");
		return 2;
	}
	char p[4096];
	for (int i = 2; i < argc; i++) {
		int triangles;
		if (mesh_arg(argv[i], p, sizeof p, &triangles))
			return 2;
		expect_triangles(p, triangles);
	}
	/* small files of the other formats: a quad (two triangles) in OFF, STL and glTF */
	snprintf(p, sizeof p, "%s/quad.off", argv[1]);
	write_file(p, "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
	expect_triangles(p, 2);
	snprintf(p, sizeof p, "%s/tri.stl", argv[1]);
	write_file(p, "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
	              "endloop\nendfacet\nendsolid t\n");
	expect_triangles(p, 1);
	snprintf(p, sizeof p, "%s/tri.gltf", argv[1]);
	write_file(p, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
	              "\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
	              "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"
	              "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],"
	              "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
	              "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
	              "\"min\":[0,0,0],\"max\":[1,1,0]}]}\n");
	expect_triangles(p, 1);

	snprintf(p, sizeof p, "%s/no_such_mesh.obj", argv[1]);
	expect_error(p, "a missing file");
	snprintf(p, sizeof p, "%s/empty.obj", argv[1]);
	write_file(p, "");
	expect_error(p, "an empty file");
	snprintf(p, sizeof p, "%s/garbage.ply", argv[1]);
	write_file(p, "ply\nformat binary_little_endian 1.0\nelement vertex 1000000\nproperty float x\nend_header\n\x01\x02");
	expect_error(p, "a truncated PLY");
	snprintf(p, sizeof p, "%s/points.obj", argv[1]);
	write_file(p, "v 0 0 0\nv 1 0 0\np 1 2\n");
	expect_error(p, "a file of points only");
	printf("%s\n", failures ? "FAIL" : "all mesh checks passed");
	return failures ? 1 : 0;
}
