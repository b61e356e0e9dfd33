/* mesh_io.c: the only file that talks to assimp. */
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "host_memory.h"
#include "loader.h"
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

int mesh_io_load_here(const char *path, scene_mesh *m, char *err, size_t errlen)
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
		scene_mesh_free(m);
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

/* Up to 8 numbers on a line, so the file stays readable and diffable. */
static void write_vectors(FILE *out, const char *block, const double (*v)[3], int n)
{
	fprintf(out, "  %s { %d", block, n);
	for (int i = 0; i < n; i++)
		fprintf(out, ",%s<%.9g, %.9g, %.9g>", i % 4 ? " " : "\n    ", v[i][0], v[i][1], v[i][2]);
	fprintf(out, "\n  }\n");
}

int mesh_io_write_mesh2(const scene_mesh *m, const char *name, const char *source, FILE *out)
{
	fprintf(out, "// %s: %d vertices and %d triangles from %s, written by eclat --export-mesh2.\n"
	        "// Vertices are printed with 9 digits, so povray and eclat read the same floats.\n",
	        name, m->n_v, m->n_faces, source);
	fprintf(out, "#declare %s = mesh2 {\n", name);
	write_vectors(out, "vertex_vectors", (const double (*)[3])m->v, m->n_v);
	if (m->nrm && m->face_nrm)   /* the normals share the vertices' indices */
		write_vectors(out, "normal_vectors", (const double (*)[3])m->nrm, m->n_nrm);
	fprintf(out, "  face_indices { %d", m->n_faces);
	for (int f = 0; f < m->n_faces; f++)
		fprintf(out, ",%s<%d, %d, %d>", f % 6 ? " " : "\n    ", m->face[f][0], m->face[f][1], m->face[f][2]);
	fprintf(out, "\n  }\n}\n");
	return ferror(out) ? -1 : 0;
}

/* ---- the loader in a child process ----
 * assimp crashes on some corrupt files (a fuzzed binary PLY makes it write out of
 * bounds), and a crash in a library would take eclat down with it. So assimp runs
 * in a child process that sends the triangles back through a pipe; a child that
 * dies is an error that names the file, and eclat goes on. A truncated binary PLY
 * header makes assimp loop for ever, so the child also has an alarm clock.
 * It is not src/loader.c's loader_run, whose child closes its stderr and is the
 * OOM killer's first pick: assimp's assertion reports and a sanitizer's reach
 * stderr here, where tests/bad.tap looks for them, and the messages name
 * --mesh-time-limit. The pipe's helpers and the error answer are loader.c's. */

static void child(int fd, const char *path, unsigned time_limit)
{
	/* a crash ends the child at once, whatever handlers the parent has (a
	 * sanitizer's or a fuzzer's would take long to report on a library) */
	static const int fatal[] = { SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL };
	for (size_t i = 0; i < sizeof fatal / sizeof *fatal; i++)
		signal(fatal[i], SIG_DFL);
	signal(SIGALRM, SIG_DFL);   /* a fuzzer's handler would report a timeout */
	alarm(time_limit);          /* 0: none; a fork starts with no alarm of its own */
	scene_mesh m;
	char err[LOADER_ERR_LEN] = "";
	int rc = mesh_io_load_here(path, &m, err, sizeof err);
	int head[4] = { rc, rc ? 0 : m.n_v, rc ? 0 : m.n_faces, !rc && m.nrm != NULL };
	int bad = loader_write(fd, head, sizeof head) ||
	          (rc && loader_write(fd, err, sizeof err)) ||
	          (!rc && loader_write(fd, m.v, (size_t)m.n_v * sizeof *m.v)) ||
	          (!rc && m.nrm && loader_write(fd, m.nrm, (size_t)m.n_v * sizeof *m.nrm)) ||
	          (!rc && loader_write(fd, m.face, (size_t)m.n_faces * sizeof *m.face));
	_exit(bad ? 1 : 0);   /* no atexit handlers: they belong to the parent */
}

double mesh_io_bytes(double n_v, double n_faces, int normals)
{
	/* the vertices (and normals), the faces (their normals' and materials'
	 * indices), and about as much again for the lowering and the BVH */
	return 2 * (n_v * sizeof(double[3]) * (normals ? 2 : 1) + n_faces * sizeof(int[3]) * 3);
}

/* 0 when a mesh this large may be allocated here; else -1 with the numbers. */
int mesh_io_fits(double n_v, double n_faces, int normals, double max_bytes, char *err, size_t errlen)
{
	double need = mesh_io_bytes(n_v, n_faces, normals);
	if (max_bytes <= 0 || need <= max_bytes)
		return 0;
	char a[32], b[32];
	host_memory_format(need, a, sizeof a);
	host_memory_format(max_bytes, b, sizeof b);
	snprintf(err, errlen, "its %.0f vertices and %.0f triangles need %s, more than the %s of memory left to the "
	         "scene (--memory-limit)", n_v, n_faces, a, b);
	return -1;
}

static int receive(int fd, scene_mesh *m, double max_bytes, char *err, size_t errlen)
{
	int head[4];
	if (loader_read(fd, head, sizeof head))
		return -2;
	if (head[0])
		return loader_take_error(fd, err, errlen);
	if (head[1] < 0 || head[2] < 0)
		return -2;
	if (mesh_io_fits(head[1], head[2], head[3], max_bytes, err, errlen))
		return -1;
	m->n_v = head[1];
	m->n_faces = head[2];
	m->v = malloc((size_t)m->n_v * sizeof *m->v + 1);
	m->face = malloc((size_t)m->n_faces * sizeof *m->face + 1);
	m->nrm = head[3] ? malloc((size_t)m->n_v * sizeof *m->nrm + 1) : NULL;
	m->face_nrm = head[3] ? malloc((size_t)m->n_faces * sizeof *m->face_nrm + 1) : NULL;
	if (!m->v || !m->face || (head[3] && (!m->nrm || !m->face_nrm)) ||
	    loader_read(fd, m->v, (size_t)m->n_v * sizeof *m->v) ||
	    (m->nrm && loader_read(fd, m->nrm, (size_t)m->n_v * sizeof *m->nrm)) ||
	    loader_read(fd, m->face, (size_t)m->n_faces * sizeof *m->face))
		return -2;
	if (m->nrm) {   /* normals share the vertices' indices */
		m->n_nrm = m->n_v;
		memcpy(m->face_nrm, m->face, (size_t)m->n_faces * sizeof *m->face);
	}
	return 0;
}

int mesh_io_load(const char *path, unsigned time_limit, double max_bytes, scene_mesh *m, char *err, size_t errlen)
{
	memset(m, 0, sizeof *m);
	if (loader_before_fork)
		loader_before_fork("assimp");
	int fd[2];
	if (pipe(fd)) {
		snprintf(err, errlen, "cannot start the mesh loader: %s", strerror(errno));
		return -1;
	}
	fflush(NULL);   /* what is buffered is printed once, by the parent */
	pid_t pid = fork();
	if (pid < 0) {
		snprintf(err, errlen, "cannot start the mesh loader: %s", strerror(errno));
		close(fd[0]);
		close(fd[1]);
		return -1;
	}
	if (pid == 0) {
		close(fd[0]);
		child(fd[1], path, time_limit);
	}
	close(fd[1]);
	int rc = receive(fd[0], m, max_bytes, err, errlen);
	close(fd[0]);
	int status = 0;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
		;
	/* all that was sent arrived: the child's exit status (a tool's at exit,
	 * under valgrind) does not matter then */
	if (rc == -2) {
		scene_mesh_free(m);
		memset(m, 0, sizeof *m);
		if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
			snprintf(err, errlen, "assimp was still reading it after %u s: the file may be "
			         "corrupt (--mesh-time-limit raises the limit)", time_limit);
		else if (WIFSIGNALED(status))
			snprintf(err, errlen, "the file is corrupt: assimp crashed reading it (%s)",
			         strsignal(WTERMSIG(status)));
		else
			snprintf(err, errlen, "the file is corrupt: assimp stopped reading it");
		return -1;
	}
	return rc;
}
