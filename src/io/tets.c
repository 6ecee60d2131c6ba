/* Tetrahedral meshes out: legacy VTK (ParaView) and TetGen .node/.ele. */
#include <inttypes.h>
#include <string.h>

#include "io/io_internal.h"

static fl_status check_tets(const char *path, size_t point_count, const uint32_t *tet,
                            size_t tet_count, fl_error *err)
{
    for (size_t i = 0; i < 4 * tet_count; i++)
        if (tet[i] >= point_count)
            return fl_fail(err, FL_ERR_USAGE, path, -1,
                           "tetrahedron %zu refers to point %" PRIu32 " of %zu", i / 4, tet[i],
                           point_count);
    return FL_OK;
}

static void write_vtk(FILE *fp, const double *xyz, size_t np, const uint32_t *tet, size_t nt)
{
    fprintf(fp,
            "# vtk DataFile Version 3.0\nflintstone tetrahedra\nASCII\n"
            "DATASET UNSTRUCTURED_GRID\nPOINTS %zu double\n",
            np);
    for (size_t i = 0; i < np; i++)
        fprintf(fp, "%.17g %.17g %.17g\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    fprintf(fp, "CELLS %zu %zu\n", nt, 5 * nt);
    for (size_t t = 0; t < nt; t++)
        fprintf(fp, "4 %" PRIu32 " %" PRIu32 " %" PRIu32 " %" PRIu32 "\n", tet[4 * t],
                tet[4 * t + 1], tet[4 * t + 2], tet[4 * t + 3]);
    fprintf(fp, "CELL_TYPES %zu\n", nt);
    for (size_t t = 0; t < nt; t++)
        fputs("10\n", fp); /* VTK_TETRA */
}

static void write_node(FILE *fp, const double *xyz, size_t np)
{
    fprintf(fp, "# firstnumber 0\n%zu 3 0 0\n", np);
    for (size_t i = 0; i < np; i++)
        fprintf(fp, "%zu %.17g %.17g %.17g\n", i, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
}

static void write_ele(FILE *fp, const uint32_t *tet, size_t nt)
{
    fprintf(fp, "# firstnumber 0\n%zu 4 0\n", nt);
    for (size_t t = 0; t < nt; t++)
        fprintf(fp, "%zu %" PRIu32 " %" PRIu32 " %" PRIu32 " %" PRIu32 "\n", t, tet[4 * t],
                tet[4 * t + 1], tet[4 * t + 2], tet[4 * t + 3]);
}

/* The .node/.ele pair: both temporaries are complete before either is renamed, so a failure
 * while writing leaves both targets untouched. */
static fl_status write_tetgen(const char *path, const double *xyz, size_t np, const uint32_t *tet,
                              size_t nt, fl_error *err)
{
    char stem[1000], node_path[1024], ele_path[1024];
    size_t n = strlen(path);
    if (n >= sizeof stem) return fl_fail(err, FL_ERR_USAGE, path, -1, "output path too long");
    memcpy(stem, path, n + 1);
    char *dot = strrchr(stem, '.');
    if (dot) *dot = '\0';
    snprintf(node_path, sizeof node_path, "%s.node", stem);
    snprintf(ele_path, sizeof ele_path, "%s.ele", stem);
    fl_out_file node, ele;
    fl_status st = fl_out_open(&node, node_path, 0, err);
    if (st) return st;
    if ((st = fl_out_open(&ele, ele_path, 0, err))) {
        fl_out_abort(&node);
        return st;
    }
    write_node(node.fp, xyz, np);
    write_ele(ele.fp, tet, nt);
    if (ferror(node.fp) || ferror(ele.fp) || fflush(node.fp) || fflush(ele.fp)) {
        fl_out_abort(&node);
        fl_out_abort(&ele);
        return fl_fail(err, FL_ERR_IO, path, -1, "write failed");
    }
    if ((st = fl_out_commit(&node, err))) {
        fl_out_abort(&ele);
        return st;
    }
    return fl_out_commit(&ele, err);
}

fl_status fl_write_tets(const char *path, const double *xyz, size_t point_count,
                        const uint32_t *tet, size_t tet_count, fl_error *err)
{
    if (!path || (!xyz && point_count) || (!tet && tet_count))
        return fl_fail(err, FL_ERR_USAGE, NULL, -1, "fl_write_tets: NULL argument");
    fl_status st = check_tets(path, point_count, tet, tet_count, err);
    if (st) return st;
    char ext[16];
    fl_path_extension(path, ext, sizeof ext);
    if (strcmp(ext, "node") == 0 || strcmp(ext, "ele") == 0)
        return write_tetgen(path, xyz, point_count, tet, tet_count, err);
    if (strcmp(ext, "vtk") != 0)
        return fl_fail(err, FL_ERR_USAGE, path, -1,
                       "unknown tetrahedral mesh format '.%s' (use .vtk, .node or .ele)", ext);
    fl_out_file out;
    if ((st = fl_out_open(&out, path, 0, err))) return st;
    write_vtk(out.fp, xyz, point_count, tet, tet_count);
    return fl_out_commit(&out, err);
}
