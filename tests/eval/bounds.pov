// bounded_by and clipped_by are parsed and ignored with a warning where each
// is written (bounds.pov.err), including POV-Ray's "bounded_by { clipped_by }", which
// bounds an object by its clip (shapesq.inc writes it).
sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } }
sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }
