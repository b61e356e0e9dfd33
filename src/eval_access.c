/* eval_access.c: file I/O security, the files a scene may make eclat read and
 * write. It is POV-Ray's [File I/O Security] (vfe/unix/unixoptions.cpp,
 * vfeplatform.cpp), restricted by default, because a scene is a program that
 * someone else may have written:
 *
 *   restricted  a scene reads from its own folder and below, the include
 *               folders (-I, $ECLAT_INCLUDE_PATH, eclat's and POV-Ray's), the
 *               system's font folders, the current folder and the --io-allow
 *               and --io-allow-write folders and below; it writes into its own
 *               folder and the current folder (not below them) and the
 *               --io-allow-write folders and below;
 *   read-only   reads anywhere, writes as restricted;
 *   none        anything the user may do.
 *
 * A folder one may write into may be read too, as in POV-Ray. Paths are
 * compared after realpath(), so "../", absolute paths and links that lead out
 * are caught; a file that does not exist yet is judged by its folder, and a link
 * to nothing is refused, as no one can tell where a write through it would go.
 * Every file a scene names is checked here before it is opened: #include,
 * #fopen, #read (through #fopen), file_exists, mesh files, image_map images and
 * text's fonts.
 *
 * POV-Ray's [Shellout Security] (forbidden by default) will go here too when INI
 * files bring Pre_Frame_Command and its kin: a command is run only when the
 * user allows shell-outs, never because a scene or an INI file asks. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "eval_int.h"

/* The system's font folders, which text's fonts may come from: Debian's
 * POV-Ray fonts in its include folder are links into /usr/share/fonts. */
static const char *const font_dirs[] = { "/usr/share/fonts", "/usr/local/share/fonts" };

struct folder {
	char *path;   /* resolved, without a trailing '/' ("/" itself is "") */
	bool below;   /* its subfolders too */
	bool write;   /* writes too (and so reads) */
};

struct eval_access {
	struct folder *dirs;
	int n;
};

static void add(struct eval_access *a, const char *dir, size_t len, bool below, bool write)
{
	char *copy = eval_xrealloc(NULL, len + 1);
	memcpy(copy, dir, len);
	copy[len] = '\0';
	char *r = realpath(copy, NULL);   /* a folder that is not there allows nothing */
	free(copy);
	if (!r)
		return;
	if (strcmp(r, "/") == 0)
		r[0] = '\0';
	a->dirs = eval_xrealloc(a->dirs, (a->n + 1) * sizeof *a->dirs);
	a->dirs[a->n++] = (struct folder){ r, below, write };
}

static void add_dir(struct eval_access *a, const char *dir, bool below, bool write)
{
	if (dir)
		add(a, dir, strlen(dir), below, write);
}

/* The folder of the scene's file (the current folder for "scene.scn"). */
static void add_scene_dir(struct eval_access *a, int scene_file)
{
	const char *name = scene_file >= 0 ? diag_source_name(scene_file) : NULL;
	if (!name)
		return;
	const char *slash = strrchr(name, '/');
	size_t len = !slash ? 1 : slash == name ? 1 : (size_t)(slash - name);
	if (!slash)
		name = ".";
	add(a, name, len, true, false);
	add(a, name, len, false, true);
}

/* The folders #include searches (find_file in eval.c), read with their subfolders. */
static void add_library_dirs(struct eval_access *a, const eval_options *opt)
{
	for (int i = 0; i < opt->n_include_dirs; i++)
		add_dir(a, opt->include_dirs[i], true, false);
	for (const char *list = getenv("ECLAT_INCLUDE_PATH"); list && *list;) {
		size_t n = strcspn(list, ":");
		if (n)
			add(a, list, n, true, false);
		list += n + (list[n] == ':');
	}
	add_dir(a, eval_installed_include_dir(), true, false);
	add_dir(a, EVAL_POV_INCLUDE_DIR, true, false);
	for (size_t i = 0; i < sizeof font_dirs / sizeof *font_dirs; i++)
		add_dir(a, font_dirs[i], true, false);
}

void eval_access_init(struct eval *e, int scene_file)
{
	const eval_options *opt = e->opt;
	struct eval_access *a = eval_xrealloc(NULL, sizeof *a);
	*a = (struct eval_access){ 0 };
	e->access = a;
	if (opt->io_security == EVAL_IO_NONE)
		return;
	add_scene_dir(a, scene_file);
	if (opt->io_current_folder)
		add_dir(a, ".", false, true);
	add_library_dirs(a, opt);
	for (int i = 0; i < opt->n_io_read_dirs; i++)
		add_dir(a, opt->io_read_dirs[i], true, false);
	for (int i = 0; i < opt->n_io_write_dirs; i++)
		add_dir(a, opt->io_write_dirs[i], true, true);
}

void eval_access_free(struct eval *e)
{
	struct eval_access *a = e->access;
	if (!a)
		return;
	for (int i = 0; i < a->n; i++)
		free(a->dirs[i].path);
	free(a->dirs);
	free(a);
	e->access = NULL;
}

static char *joined(const char *dir, const char *rest)
{
	char *p = NULL;
	if (asprintf(&p, "%s/%s", strcmp(dir, "/") == 0 ? "" : dir, rest) < 0)
		eval_xrealloc(NULL, (size_t)-1 / 2);
	return p;
}

/* path, absolute, with its links and ".." resolved as far as it exists; what
 * does not exist yet follows as written (opening it fails, or a write creates
 * its last name in the resolved folder). NULL with errno set where that cannot
 * be told: a link to nothing (ENOENT), a loop of links, a folder that may not
 * be searched. */
static char *resolve(const char *path)
{
	char *r = realpath(path, NULL);
	if (r || errno != ENOENT)
		return r;
	size_t n = strlen(path);   /* path[0, n) is the part tried, with its last '/' */
	for (;;) {
		while (n > 1 && path[n - 1] == '/')
			n--;
		while (n > 0 && path[n - 1] != '/')
			n--;
		char *head = n ? strndup(path, n) : eval_xstrdup(".");
		if (!head)
			eval_xrealloc(NULL, (size_t)-1 / 2);
		r = realpath(head, NULL);
		int why = errno;
		free(head);
		if (r)
			break;
		if (why != ENOENT || n <= 1) {
			errno = why;
			return NULL;
		}
	}
	const char *rest = path + n;   /* from the first name that is not there */
	char *p = joined(r, rest), *first = eval_xstrdup(p);
	first[strlen(p) - strlen(rest) + strcspn(rest, "/")] = '\0';
	struct stat st;
	bool link = lstat(first, &st) == 0;   /* there, yet realpath did not find it: a link to nothing */
	free(first);
	free(r);
	if (link) {
		free(p);
		errno = ENOENT;
		return NULL;
	}
	return p;
}

/* Whether the resolved path is in the folder, or below it. The folder itself
 * counts: no file can be read or written as a folder, and "cannot read '.': Is a
 * directory" says more than a refusal. */
static bool inside(const struct folder *f, const char *path)
{
	size_t n = strlen(f->path);
	if (strncmp(path, f->path, n) != 0 || (path[n] != '/' && path[n] != '\0'))
		return false;
	return path[n] == '\0' || f->below || strchr(path + n + 1, '/') == NULL;
}

static bool permitted(const struct eval *e, const char *resolved, bool write)
{
	int level = e->opt->io_security;
	if (level == EVAL_IO_NONE || (level == EVAL_IO_READ_ONLY && !write))
		return true;
	const struct eval_access *a = e->access;
	for (int i = 0; resolved && a && i < a->n; i++)
		if ((a->dirs[i].write || !write) && inside(&a->dirs[i], resolved))
			return true;
	return false;
}

bool eval_access_allowed(struct eval *e, const char *path, bool write)
{
	if (e->opt->io_security == EVAL_IO_NONE)
		return true;
	char *r = resolve(path);
	bool ok = permitted(e, r, write);
	free(r);
	return ok;
}

static int allowed(struct eval *e, const char *path, bool write)
{
	if (!write && e->opt->on_read)
		e->opt->on_read(e->opt->on_read_ctx, path);
	return 0;
}

int eval_access(struct eval *e, const char *path, bool write, src_loc loc, const char *what)
{
	if (e->opt->io_security == EVAL_IO_NONE)
		return allowed(e, path, write);
	char *r = resolve(path);
	if (permitted(e, r, write)) {
		free(r);
		return allowed(e, path, write);
	}
	const char *verb = write ? "write" : "read";
	if (!r && errno == ENOENT) {
		eval_error(e, loc, "refusing to %s '%s' for %s: it is a link to nothing (--io-security none allows it)",
		           verb, path, what);
		return -1;
	}
	if (!r) {   /* the open would fail the same way; the check fails first */
		eval_error(e, loc, "refusing to %s '%s' for %s: cannot tell where it is: %s", verb, path, what,
		           strerror(errno));
		return -1;
	}
	char shown[PATH_MAX + 16] = "";
	if (strcmp(r, path) != 0)
		snprintf(shown, sizeof shown, "'%s', ", r);
	*strrchr(r, '/') = '\0';
	eval_error(e, loc, "refusing to %s '%s' for %s: it is %soutside the folders a scene may %s "
	           "(--io-allow%s %s allows it)", verb, path, what, shown, verb, write ? "-write" : "", r[0] ? r : "/");
	free(r);
	return -1;
}
