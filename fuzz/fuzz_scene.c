/* fuzz_scene.c: libFuzzer target for the host side of a render: lexer, parser,
 * evaluator, and lowering with its BVH builds (no rendering, no OpenCL), where
 * the evaluator's doubles become the device's floats. One input is one scene
 * file.
 *
 *   make fuzz FUZZ_SECONDS=60          (builds with clang, runs both targets)
 *   fuzz/fuzz_scene crash-...   (replays one input with its messages; make fuzz drops
 *   them with -close_fd_mask=2, and keeps libFuzzer's and the sanitizers' reports)
 *
 * The limits are lowered so that a loop or a recursion that never ends costs
 * milliseconds, not the fuzzer's -timeout: the evaluator must stop it itself.
 *
 * An input is a scene that may #fopen and #write whatever it likes. It is read
 * as the file fuzz.scn of a scratch folder of its own, and the current folder
 * does not count as the command line's does, so the evaluator's file I/O
 * security (src/eval_access.c, restricted) lets it write only there; the folder
 * is emptied after each input, so that no input reads what another wrote. */
#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "diag.h"
#include "eval.h"
#include "image.h"
#include "lower.h"
#include "parse.h"

/* The evaluator reads image_map files through OpenImageIO (image_oiio.cpp,
 * C++), which this C target does not link: here no image can be read, so an
 * image_map takes the path of a file that will not load, as a missing one
 * does. Image files need a fuzz target of their own. */
int image_read(const char *path, const image_limits *lim, image_data *out, char *err, size_t errlen)
{
	(void)path, (void)lim;
	memset(out, 0, sizeof *out);
	snprintf(err, errlen, "the scene fuzzer reads no images");
	return -1;
}

int image_indices(const char *path, const image_limits *lim, unsigned char **out, int *width, int *height)
{
	(void)path, (void)lim, (void)width, (void)height;
	*out = NULL;
	return 0;
}

static char scratch[64];

static void remove_scratch(void)
{
	DIR *d = opendir(scratch);
	struct dirent *ent;
	char path[sizeof scratch + 256];
	while (d && (ent = readdir(d)) != NULL)
		if (strcmp(ent->d_name, ".") != 0 && strcmp(ent->d_name, "..") != 0) {
			snprintf(path, sizeof path, "%s/%s", scratch, ent->d_name);
			unlink(path);
		}
	if (d)
		closedir(d);
}

static void remove_scratch_folder(void)
{
	remove_scratch();
	rmdir(scratch);
}

/* The scene's own folder, made once. */
static const char *scratch_folder(void)
{
	if (scratch[0])
		return scratch;
	const char *tmp = getenv("TMPDIR");
	snprintf(scratch, sizeof scratch, "%.40s/fuzz_scene.XXXXXX", tmp && *tmp ? tmp : "/tmp");
	if (!mkdtemp(scratch)) {
		perror(scratch);
		abort();
	}
	atexit(remove_scratch_folder);
	return scratch;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = malloc(size + 1);
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	char name[sizeof scratch + 16];
	snprintf(name, sizeof name, "%s/fuzz.scn", scratch_folder());
	ast_node *tree = parse_text(name, text, size);   /* diag owns text now */
	if (tree) {
		eval_options opt = eval_options_default();
		opt.max_loop_iterations = 20000;
		opt.max_macro_depth = 64;
		opt.max_include_depth = 8;
		opt.mesh_time_limit = 3;   /* under libFuzzer's -timeout */
		opt.io_security = EVAL_IO_RESTRICTED;   /* the default, said here because it matters */
		scene s;
		scene_init(&s);
		if (eval_scene(tree, &s, &opt) == 0 && diag_error_count() == 0) {
			lower_result lr;
			lower_scene(&s, NULL, &lr);
			lower_free(&lr);
		}
		scene_free(&s);
		ast_free(tree);
	}
	diag_free_all();
	remove_scratch();
	return 0;
}
