/* loader.c: libraries that read hostile files run in a child process (see loader.h). */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "loader.h"

int loader_write(int fd, const void *p, size_t n)
{
	for (const char *c = p; n > 0;) {
		ssize_t k = write(fd, c, n);
		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0)
			return -1;
		c += k;
		n -= (size_t)k;
	}
	return 0;
}

int loader_read(int fd, void *p, size_t n)
{
	for (char *c = p; n > 0;) {
		ssize_t k = read(fd, c, n);
		if (k < 0 && errno == EINTR)
			continue;
		if (k <= 0)
			return -1;
		c += k;
		n -= (size_t)k;
	}
	return 0;
}

int loader_take_error(int fd, char *err, size_t errlen)
{
	char msg[LOADER_ERR_LEN];
	if (loader_read(fd, msg, sizeof msg))
		return -2;
	msg[sizeof msg - 1] = '\0';   /* a child gone wrong may send no end */
	snprintf(err, errlen, "%s", msg);
	return -1;
}

const char *loader_not_a_file(const char *path)
{
	struct stat st;
	if (stat(path, &st))
		return NULL;
	if (S_ISDIR(st.st_mode))
		return "it is a folder, not a file";
	if (!S_ISREG(st.st_mode))
		return "it is not a regular file";   /* a FIFO would block the reader for ever */
	if (st.st_size == 0)
		return "the file is empty";
	return NULL;
}

static void child(int fd, unsigned time_limit, loader_work work, void *arg)
{
	/* a crash ends the child at once, whatever handlers the parent has (a
	 * sanitizer's or a fuzzer's would take long to report on a library) */
	static const int fatal[] = { SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL };
	for (size_t i = 0; i < sizeof fatal / sizeof *fatal; i++)
		signal(fatal[i], SIG_DFL);
	signal(SIGALRM, SIG_DFL);   /* a fuzzer's handler would report a timeout */
	signal(SIGPIPE, SIG_DFL);   /* a parent that stopped listening ends the child */
	alarm(time_limit);          /* 0: none; a fork starts with no alarm of its own */
	/* were memory to run out while a decoder is at a hostile file, the kernel
	 * should end the child, not eclat */
	int adj = open("/proc/self/oom_score_adj", O_WRONLY);
	if (adj >= 0) {
		if (write(adj, "1000", 4) < 0) { /* an old kernel: no matter */ }
		close(adj);
	}
	/* libraries print their complaints (libpng's "Read error"); the answer
	 * carries the one that matters, at the scene's line */
	int null = open("/dev/null", O_WRONLY);
	if (null >= 0 && null != STDERR_FILENO) {
		dup2(null, STDERR_FILENO);
		close(null);
	}
	_exit(work(fd, arg) ? 1 : 0);   /* no atexit handlers: they belong to the parent */
}

void (*loader_before_fork)(const char *library);

int loader_run(const char *library, unsigned time_limit, loader_work work, loader_take take, void *arg,
               char *err, size_t errlen)
{
	if (loader_before_fork)
		loader_before_fork(library);
	int fd[2];
	if (pipe(fd)) {
		snprintf(err, errlen, "cannot start %s in a child process: %s", library, strerror(errno));
		return -1;
	}
	fflush(NULL);   /* what is buffered is printed once, by the parent */
	pid_t pid = fork();
	if (pid < 0) {
		snprintf(err, errlen, "cannot start %s in a child process: %s", library, strerror(errno));
		close(fd[0]);
		close(fd[1]);
		return -1;
	}
	if (pid == 0) {
		close(fd[0]);
		child(fd[1], time_limit, work, arg);
	}
	close(fd[1]);
	int rc = take(fd[0], arg, err, errlen);
	close(fd[0]);
	int status = 0;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
		;
	/* all that was sent arrived: the child's exit status (a tool's at exit,
	 * under valgrind) does not matter then */
	if (rc != -2)
		return rc;
	if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
		snprintf(err, errlen, "%s was still reading it after %u s: the file may be corrupt "
		         "(--load-time-limit raises the limit)", library, time_limit);
	else if (WIFSIGNALED(status))
		snprintf(err, errlen, "the file is corrupt: %s crashed reading it (%s)", library,
		         strsignal(WTERMSIG(status)));
	else
		snprintf(err, errlen, "the file is corrupt: %s stopped reading it", library);
	return -1;
}
