/* mesh_io.c: the only file that talks to assimp. */
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_io.h"

/* Triangulate polygons, flatten the node hierarchy into world positions, join
 * shared vertices (the BVH and smooth normals want them shared), and sort by
 * primitive type so that points and lines can be dropped. */
#define IMPORT_FLAGS (aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | \
                      aiProcess_PreTransformVertices | aiProcess_SortByPType)

/* Debian's assimp is built with its internal asserts on, and a post-processing
 * step that meets a face the loader left broken (a truncated PLY) aborts the whole
 * program. So the file is read first with validation only, its faces are checked
 * here, and the steps run only on a scene that passed. */
static int check_faces(const struct aiScene *sc, char *err, size_t errlen)
{
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *mesh = sc->mMeshes[i];
		for (unsigned f = 0; f < mesh->mNumFaces; f++) {
			const struct aiFace *face = &mesh->mFaces[f];
			if (face->mNumIndices == 0 || !face->mIndices) {
				snprintf(err, errlen, "face %u of mesh %u has no vertices (a truncated file?)", f, i);
				return -1;
			}
			for (unsigned k = 0; k < face->mNumIndices; k++)
				if (face->mIndices[k] >= mesh->mNumVertices) {
					snprintf(err, errlen, "face %u of mesh %u uses vertex %u of %u (a corrupt file?)", f, i,
					         face->mIndices[k], mesh->mNumVertices);
					return -1;
				}
		}
	}
	return 0;
}

static int count(const struct aiScene *sc, unsigned *verts, unsigned *faces, int *normals)
{
	*verts = *faces = 0;
	*normals = 1;
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *mesh = sc->mMeshes[i];
		if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
			continue;
		*verts += mesh->mNumVertices;
		for (unsigned f = 0; f < mesh->mNumFaces; f++)
			*faces += mesh->mFaces[f].mNumIndices == 3;
		*normals &= mesh->mNormals != NULL;
	}
	return *faces > 0 && *verts < 0x7fffffffu && *faces < 0x7fffffffu;
}

static void copy_mesh(const struct aiMesh *mesh, scene_mesh *m, int base)
{
	for (unsigned v = 0; v < mesh->mNumVertices; v++) {
		const struct aiVector3D *p = &mesh->mVertices[v];
		double *dst = m->v[base + v];
		dst[0] = p->x;
		dst[1] = p->y;
		dst[2] = p->z;
		if (m->nrm) {
			const struct aiVector3D *n = &mesh->mNormals[v];
			m->nrm[base + v][0] = n->x;
			m->nrm[base + v][1] = n->y;
			m->nrm[base + v][2] = n->z;
		}
	}
	for (unsigned f = 0; f < mesh->mNumFaces; f++) {
		const struct aiFace *face = &mesh->mFaces[f];
		if (face->mNumIndices != 3)
			continue;
		int *dst = m->face[m->n_faces++];
		for (int k = 0; k < 3; k++)
			dst[k] = base + (int)face->mIndices[k];
	}
}

int mesh_io_load(const char *path, scene_mesh *m, char *err, size_t errlen)
{
	memset(m, 0, sizeof *m);
	const struct aiScene *sc = aiImportFile(path, aiProcess_ValidateDataStructure);
	if (sc && check_faces(sc, err, errlen)) {
		aiReleaseImport(sc);
		return -1;
	}
	if (sc)
		sc = aiApplyPostProcessing(sc, IMPORT_FLAGS);   /* releases the scene when a step fails */
	if (!sc) {
		snprintf(err, errlen, "%s", aiGetErrorString());
		return -1;
	}
	unsigned nv, nf;
	int normals;
	if (!count(sc, &nv, &nf, &normals)) {
		snprintf(err, errlen, "the file holds no triangles");
		aiReleaseImport(sc);
		return -1;
	}
	m->v = malloc(nv * sizeof *m->v);
	m->face = malloc(nf * sizeof *m->face);
	m->nrm = normals ? malloc(nv * sizeof *m->nrm) : NULL;
	if (!m->v || !m->face || (normals && !m->nrm)) {
		free(m->v);
		free(m->face);
		free(m->nrm);
		memset(m, 0, sizeof *m);
		snprintf(err, errlen, "out of memory for %u triangles", nf);
		aiReleaseImport(sc);
		return -1;
	}
	int base = 0;
	for (unsigned i = 0; i < sc->mNumMeshes; i++) {
		const struct aiMesh *mesh = sc->mMeshes[i];
		if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
			continue;
		copy_mesh(mesh, m, base);
		base += (int)mesh->mNumVertices;
	}
	m->n_v = base;
	if (m->nrm) {
		m->n_nrm = base;
		m->face_nrm = malloc(nf * sizeof *m->face_nrm);   /* normals share the vertices' indices */
		if (m->face_nrm)
			memcpy(m->face_nrm, m->face, nf * sizeof *m->face);
	}
	aiReleaseImport(sc);
	return 0;
}
