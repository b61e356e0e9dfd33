/* host_memory.c: see host_memory.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/sysinfo.h>

#include "host_memory.h"

double host_memory_available(void)
{
	/* MemAvailable counts the page cache the kernel would give back; sysinfo's
	 * free memory does not, and would refuse a scene that fits */
	FILE *f = fopen("/proc/meminfo", "r");
	if (f) {
		char line[128];
		unsigned long long kib;
		while (fgets(line, sizeof line, f))
			if (sscanf(line, "MemAvailable: %llu kB", &kib) == 1) {
				fclose(f);
				return (double)kib * 1024;
			}
		fclose(f);
	}
	struct sysinfo si;
	if (sysinfo(&si))
		return 0;
	return ((double)si.freeram + si.bufferram) * si.mem_unit;
}

int host_memory_parse(const char *s, double *bytes)
{
	char *end;
	double v = strtod(s, &end);
	if (end == s || !(v > 0) || v > 1e18)
		return -1;
	static const char units[] = "KMGT";
	const char *u = *end ? strchr(units, *end & ~0x20) : NULL;
	if (*end && (!u || (end[1] && strcmp(end + 1, "iB") && strcmp(end + 1, "B"))))
		return -1;
	for (const char *p = units; u && p <= u; p++)
		v *= 1024;
	*bytes = v;
	return 0;
}

void host_memory_format(double bytes, char *out, int n)
{
	if (bytes >= 1024.0 * 1024 * 1024)
		snprintf(out, n, "%.2f GiB", bytes / (1024.0 * 1024 * 1024));
	else if (bytes >= 1024.0 * 1024)
		snprintf(out, n, "%.1f MiB", bytes / (1024.0 * 1024));
	else
		snprintf(out, n, "%.0f KiB", bytes / 1024.0);
}
