// clipped_by clips (a CSG object whose clipping leaves are never seen), and
// bounded_by is read without a word (bounds.pov.err is empty): eclat's BVH
// needs no hint, and POV-Ray's "bounded_by { clipped_by }" (shapesq.inc writes
// it) bounds an object by its clip; "clipped_by { bounded_by }" clips by the bound.
sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } }
sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }
