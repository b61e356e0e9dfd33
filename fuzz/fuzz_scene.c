/* fuzz_scene.c: libFuzzer target for the host side of a render: lexer, parser,
 * evaluator, and lowering with its BVH builds (no rendering, no OpenCL), where
 * the evaluator's doubles become the device's floats. One input is one scene
 * file.
 *
 *   make fuzz FUZZ_SECONDS=60          (builds with clang, runs both targets)
 *   FUZZ_VERBOSE=1 fuzz/fuzz_scene crash-...   (replays one input with its messages)
 *
 * The limits are lowered so that a loop or a recursion that never ends costs
 * milliseconds, not the fuzzer's -timeout: the evaluator must stop it itself. */
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
int image_read(const char *path, long max_texels, image_data *out, char *err, size_t errlen)
{
	(void)path, (void)max_texels;
	memset(out, 0, sizeof *out);
	snprintf(err, errlen, "the scene fuzzer reads no images");
	return -1;
}

static int quiet_stderr(void)
{
	if (getenv("FUZZ_VERBOSE"))
		return -1;
	int saved = dup(2), null = open("/dev/null", O_WRONLY);
	if (saved >= 0 && null >= 0)
		dup2(null, 2);
	if (null >= 0)
		close(null);
	return saved;
}

static void restore_stderr(int saved)
{
	if (saved >= 0) {
		dup2(saved, 2);
		close(saved);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = malloc(size + 1);
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	int saved = quiet_stderr();
	ast_node *tree = parse_text("fuzz.scn", text, size);   /* diag owns text now */
	if (tree) {
		eval_options opt = eval_options_default();
		opt.max_loop_iterations = 20000;
		opt.max_macro_depth = 64;
		opt.max_include_depth = 8;
		opt.mesh_time_limit = 3;   /* under libFuzzer's -timeout */
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
	restore_stderr(saved);
	return 0;
}
