/* fuzz_cli.c: libFuzzer target for POV-Ray's command line and INI files as
 * eclat reads them (src/cli_pov.c, src/cli_ini.c). An input is the arguments,
 * one a line; after a line "%%" comes an INI file, written to a temporary
 * file whose name is added as the last argument (so its keys, sections,
 * continuations and includes of itself are read as from the command line).
 * The parser ends a bad command line with exit(1), as it should: the target
 * links exit to __wrap_exit (-Wl,--wrap=exit), which jumps back here, so an
 * error is one outcome among others and a crash, a hang or a sanitizer report
 * is a finding. The parser keeps its strings until exit, by design; the
 * target gives them back after each input (cli_pov_release), or a long run
 * would reach libFuzzer's memory limit. make fuzz runs it with
 * -close_fd_mask=2: the parser's messages are dropped, libFuzzer's and the
 * sanitizers' reports are not.
 *
 *   make fuzz FUZZ_SECONDS=60
 *   fuzz/fuzz_cli crash-...   (replays one input, with its messages) */
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli_pov.h"

/* A part of eclat's own options (src/main.c's are static there): enough for
 * the parser to tell an option that takes an argument from one that does not. */
static const struct option longopts[] = {
	{ "output", required_argument, NULL, 'o' }, { "width", required_argument, NULL, 'W' },
	{ "height", required_argument, NULL, 'H' }, { "samples", required_argument, NULL, 's' },
	{ "quiet", no_argument, NULL, 'q' }, { "declare", required_argument, NULL, 'D' },
	{ "include-dir", required_argument, NULL, 'I' }, { "seed", required_argument, NULL, 256 },
	{ "integrator", required_argument, NULL, 257 }, { "allow-shellout", no_argument, NULL, 258 },
	{ NULL, 0, NULL, 0 },
};
static const char shortopts[] = "o:W:H:s:qD:I:";

static jmp_buf back;
static int armed;

void __real_exit(int status);
void __wrap_exit(int status)
{
	if (armed)
		longjmp(back, status + 1);
	__real_exit(status);
}

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = malloc(size + 1);
	if (!text)
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	char *ini = strstr(text, "\n%%\n");
	if (ini) {
		*ini = '\0';
		ini += 4;
	}
	static char *argv[MAX_ARGS + 3];
	int argc = 0;
	argv[argc++] = "eclat";
	for (char *line = text, *next; line && argc < MAX_ARGS; line = next) {
		next = strchr(line, '\n');
		if (next)
			*next++ = '\0';
		if (*line)
			argv[argc++] = line;
	}
	char path[96] = "";
	if (ini) {
		const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
		snprintf(path, sizeof path, "%.40s/fuzz_cli_XXXXXX.ini", dir);
		int fd = mkstemps(path, 4);
		if (fd >= 0) {
			if (write(fd, ini, strlen(ini)) < 0) { /* an empty INI file, then */ }
			close(fd);
			argv[argc++] = path;
		}
	}
	argv[argc] = NULL;
	cli_pov pov;
	memset(&pov, 0, sizeof pov);
	char **out = NULL;
	armed = 1;
	if (setjmp(back) == 0) {
		int n = cli_pov_args(argc, argv, longopts, shortopts, &pov, &out);
		if (n > 0 && out && out[n] != NULL)
			abort();   /* the list must end where its count says */
		cli_frame f;
		cli_pov_frame(&pov, &f);
		int rect[4];
		if (cli_pov_region(&pov, 320, 240, rect) == 1 &&
		    (rect[0] < 0 || rect[1] < 0 || rect[2] >= 320 || rect[3] >= 240 || rect[0] > rect[2] || rect[1] > rect[3]))
			abort();   /* a region inside the image, or an error */
		char *name = cli_pov_output(&pov, &f, "scene.pov", NULL);
		free(name);
	}
	armed = 0;
	diag_free_all();   /* the INI files' text */
	cli_pov_release();
	if (path[0])
		unlink(path);
	free(text);
	return 0;
}
