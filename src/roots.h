/* roots.h: the real roots of a polynomial in one variable, for the shapes whose
 * rays meet them at the roots of one (torus, poly). Its twin on the device is
 * kernels/roots.cl: the same steps in the same order, so the host's trace()
 * and the kernels find the same roots. */
#ifndef ECLAT_ROOTS_H
#define ECLAT_ROOTS_H

/* POV-Ray's highest order of a polynomial (MAX_ORDER in its polysolv.h). */
#define ROOTS_MAX_ORDER 35

/* The roots in (a, b] of c[0] + c[1] x + ... + c[n] x^n (n at most
 * ROOTS_MAX_ORDER; leading zeros are dropped), in increasing order, at most
 * max of them, into out; returns how many. A root of even multiplicity, where
 * the polynomial touches zero without crossing it, is found only where it is
 * exactly zero. */
int roots_find(const double *c, int n, double a, double b, double *out, int max);

#endif
