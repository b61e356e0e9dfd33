/* x11_window.c: what tests/preview.test does to eclat's preview window on an
 * X server (Xvfb): a screenshot taken from the server, a key pressed, the
 * window closed as a window manager closes it.
 *
 *   x11_window TITLE [--wait-file FILE] [--wait-drawn] [--shot OUT.ppm] [--key KEYSYM | --close]
 *              [--timeout S]
 *
 * Waits (at most S seconds, default 60) for a viewable window whose name
 * begins with TITLE, with --wait-file for FILE to exist, with --wait-drawn
 * for the window to show something other than black; then takes the
 * screenshot (binary PPM), then sends the key or the close request. Exits 0,
 * or 1 with a message. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <X11/Xlib.h>
#include <X11/Xutil.h>

/* A window can be destroyed between XQueryTree naming it and the next request
 * about it (the previous case's window closing as this one opens). Xlib's
 * default handler exits on that BadWindow; here the request just fails and the
 * search goes on. */
static int ignore_error(Display *d, XErrorEvent *e)
{
	(void)d, (void)e;
	return 0;
}

static Window find(Display *d, Window w, const char *title)
{
	XTextProperty name;
	XWindowAttributes a;
	if (XGetWMName(d, w, &name) && name.value) {
		int match = strncmp((const char *)name.value, title, strlen(title)) == 0;
		XFree(name.value);
		if (match && XGetWindowAttributes(d, w, &a) && a.map_state == IsViewable)
			return w;
	}
	Window root, parent, *kids = NULL, found = 0;
	unsigned n = 0;
	if (!XQueryTree(d, w, &root, &parent, &kids, &n))
		return 0;
	for (unsigned i = 0; i < n && !found; i++)
		found = find(d, kids[i], title);
	if (kids)
		XFree(kids);
	return found;
}

/* Where a channel's mask puts it, as 8 bits. */
static unsigned channel(unsigned long pixel, unsigned long mask)
{
	int shift = 0;
	while (mask && !(mask & 1)) {
		mask >>= 1;
		shift++;
	}
	unsigned long v = (pixel >> shift) & mask;
	return mask ? (unsigned)(v * 255 / mask) : 0;
}

/* 1 when some pixel of the window is not black. */
static int drawn(Display *d, Window w)
{
	XWindowAttributes a;
	if (!XGetWindowAttributes(d, w, &a))
		return 0;
	XImage *im = XGetImage(d, w, 0, 0, a.width, a.height, AllPlanes, ZPixmap);
	int any = 0;
	for (int y = 0; im && y < a.height && !any; y++)
		for (int x = 0; x < a.width && !any; x++)
			any = (XGetPixel(im, x, y) & (im->red_mask | im->green_mask | im->blue_mask)) != 0;
	if (im)
		XDestroyImage(im);
	return any;
}

static int shot(Display *d, Window w, const char *path)
{
	XWindowAttributes a;
	XImage *im = XGetWindowAttributes(d, w, &a) ? XGetImage(d, w, 0, 0, a.width, a.height, AllPlanes, ZPixmap)
	                                            : NULL;
	FILE *f = im ? fopen(path, "wb") : NULL;
	if (!f) {
		fprintf(stderr, "x11_window: cannot take or write the screenshot %s\n", path);
		return 1;
	}
	fprintf(f, "P6\n%d %d\n255\n", a.width, a.height);
	for (int y = 0; y < a.height; y++)
		for (int x = 0; x < a.width; x++) {
			unsigned long p = XGetPixel(im, x, y);
			fputc(channel(p, im->red_mask), f);
			fputc(channel(p, im->green_mask), f);
			fputc(channel(p, im->blue_mask), f);
		}
	XDestroyImage(im);
	return fclose(f) != 0;
}

static void key(Display *d, Window w, const char *sym)
{
	XSetInputFocus(d, w, RevertToParent, CurrentTime);
	XSync(d, False);
	usleep(100000);   /* the focus reaches the client before the key */
	XKeyEvent e = { .type = KeyPress, .display = d, .window = w, .root = DefaultRootWindow(d),
	                .subwindow = None, .time = CurrentTime, .same_screen = True,
	                .keycode = XKeysymToKeycode(d, XStringToKeysym(sym)) };
	XSendEvent(d, w, True, KeyPressMask, (XEvent *)&e);
	e.type = KeyRelease;
	XSendEvent(d, w, True, KeyReleaseMask, (XEvent *)&e);
}

static void close_window(Display *d, Window w)
{
	XClientMessageEvent e = { .type = ClientMessage, .window = w, .format = 32,
	                          .message_type = XInternAtom(d, "WM_PROTOCOLS", False) };
	e.data.l[0] = (long)XInternAtom(d, "WM_DELETE_WINDOW", False);
	e.data.l[1] = CurrentTime;
	XSendEvent(d, w, False, NoEventMask, (XEvent *)&e);
}

int main(int argc, char **argv)
{
	const char *title = argc > 1 ? argv[1] : NULL, *wait_file = NULL, *out = NULL, *sym = NULL;
	int close_it = 0, wait_drawn = 0;
	double timeout = 60;
	for (int i = 2; i < argc; i++) {
		if (strcmp(argv[i], "--close") == 0)
			close_it = 1;
		else if (strcmp(argv[i], "--wait-drawn") == 0)
			wait_drawn = 1;
		else if (i + 1 < argc && strcmp(argv[i], "--wait-file") == 0)
			wait_file = argv[++i];
		else if (i + 1 < argc && strcmp(argv[i], "--shot") == 0)
			out = argv[++i];
		else if (i + 1 < argc && strcmp(argv[i], "--key") == 0)
			sym = argv[++i];
		else if (i + 1 < argc && strcmp(argv[i], "--timeout") == 0)
			timeout = atof(argv[++i]);
		else
			title = NULL;
	}
	Display *d = title ? XOpenDisplay(NULL) : NULL;
	if (!d) {
		fprintf(stderr, title ? "x11_window: no X display\n"
		        : "usage: x11_window TITLE [--wait-file F] [--wait-drawn] [--shot OUT.ppm] [--key KEYSYM | --close] "
		          "[--timeout S]\n");
		return 1;
	}
	XSetErrorHandler(ignore_error);
	Window w = 0;
	for (double t = 0; t < timeout; t += 0.05) {
		w = find(d, DefaultRootWindow(d), title);
		if (w && (!wait_file || access(wait_file, F_OK) == 0) && (!wait_drawn || drawn(d, w)))
			break;
		w = 0;
		usleep(50000);
	}
	if (!w) {
		fprintf(stderr, "x11_window: no window '%s'%s%s%s after %g s\n", title, wait_drawn ? " drawn" : "",
		        wait_file ? " and no " : "", wait_file ? wait_file : "", timeout);
		return 1;
	}
	int rc = out ? shot(d, w, out) : 0;
	if (sym)
		key(d, w, sym);
	if (close_it)
		close_window(d, w);
	XSync(d, False);
	XCloseDisplay(d);
	return rc;
}
