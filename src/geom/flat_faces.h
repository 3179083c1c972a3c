/*
 * flat_faces.h — a closed triangle mesh's flat faces cut into as few
 * triangles as their outlines need.
 */
#ifndef RAYSCAD_GEOM_FLAT_FACES_H
#define RAYSCAD_GEOM_FLAT_FACES_H

/* Merge the triangles of T[0 .. *nt) over V (counter-clockwise from
 * outside, closed: every edge once each way) that share a plane (within
 * tol), an edge and, where tag is not NULL, a tag ((*tag)[t] of triangle t:
 * a colour, say) into faces, and cut each face again from its outline
 * (earcut.h): its inner vertices gone, and a vertex along a straight
 * stretch of its outline gone where the only other face at it is the one
 * across that stretch.  *T is replaced (realloc'd) and *nt updated; a face
 * whose outline touches itself or will not cut keeps its triangles; *tag
 * follows *T.  Vertices are not moved or renumbered (some may be left
 * unused).  0, or -1 when out of memory (T and tag unchanged). */
int geom_merge_flat_faces(const double (*V)[3], int nv, int (**T)[3], int **tag, int *nt,
                          double tol);

#endif
