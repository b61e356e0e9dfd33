// The reference of the smooth distribution 3 case: a perspective camera.
#include "world.inc"
camera { location <0, 2, -7> direction z * 1.5 right x * 4 / 3 up y }
