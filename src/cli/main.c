/* The `flintstone` command: parses the subcommand and hands over. Each subcommand lives in its
 * own file (cmd_<name>.c) and follows the contract in cli.h. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/commands.h"

static const cli_command commands[] = {
    {"demo", "run the whole pipeline on the bundled inputs: demo-out/report.html", cmd_demo},
    {"report", "the same pipeline on your own points or mesh, with an HTML report", cmd_report},
    {"check", "report topology, validity and measures of a mesh or polygon file", cmd_check},
    {"delaunay", "Delaunay triangulation of 2D/3D points, regular triangulation of balls",
     cmd_delaunay},
    {"graph", "γ-neighbourhood graphs and the classical graphs (hull, Delaunay, Gabriel, ...)",
     cmd_graph},
    {"reconstruct", "the boundary through every point: simple polygon (2D), genus-0 mesh (3D)",
     cmd_reconstruct},
    {"hal", "flintstone tree of a polygon: approximation by level or certified error", cmd_hal},
    {"inside", "point inclusion in a polygon through its flintstone tree", cmd_inside},
    {"intersect", "do two polygons' boundaries intersect (flintstone trees)", cmd_intersect},
    {"closest", "closest points on a mesh or polyline (Meshsweeper hierarchy)", cmd_closest},
    {"hausdorff", "certified Hausdorff distance between two meshes or polylines", cmd_hausdorff},
    {"render", "pictures: meshes, balls, 3D points to PNG; 2D points and polygons to SVG",
     cmd_render},
    {"smooth", "G1 cubic Bézier curve or surface through a polygon's or mesh's vertices",
     cmd_smooth},
    {"skin", "closed triangle mesh of the skin surface of a ball set", cmd_skin},
    {"balls", "union of balls approximating a closed polyhedron within epsilon", cmd_balls},
    {"version", "print the version", cmd_version},
};

static void usage(FILE *fp)
{
    fprintf(fp, "usage: flintstone <command> [options]\n"
                "       flintstone --help | --version\n\n"
                "Closed object boundaries from scattered points.\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(fp, "  %-12s %s\n", commands[i].name, commands[i].summary);
    fprintf(fp, "\nEvery command takes --help, -o PATH (format by extension), --json, --quiet,\n"
                "and --max-memory SIZE (default: the memory available at start; none = no limit).\n"
                "Exit codes: 0 ok, 1 usage, 2 bad input, 3 could not complete, 4 I/O failure.\n");
}

int cmd_version(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    printf("flintstone %s\n", fl_version());
    return 0;
}

/* Nothing lost (issue #14): an -o naming one of the command's own input files (the same
 * file, by device and inode, however it is spelt) is refused before anything runs, so a
 * command can never replace the user's input with its output. */
static int output_is_an_input(int argc, char **argv)
{
    for (int i = 2; i + 1 < argc; i++) {
        struct stat out;
        if ((strcmp(argv[i], "-o") != 0 && strcmp(argv[i], "--output") != 0) ||
            stat(argv[i + 1], &out) != 0)
            continue;
        for (int j = 2; j < argc; j++) {
            struct stat in;
            if (j == i + 1 || argv[j][0] == '-' || stat(argv[j], &in) != 0) continue;
            if (in.st_dev == out.st_dev && in.st_ino == out.st_ino)
                return cli_fail(1, "-o %s is also an input file; refusing to overwrite it",
                                argv[i + 1]);
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    int code = cli_memory_limit_setup(&argc, argv);
    if (code) return code;
    if (argc < 2) {
        usage(stderr);
        return 1;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("flintstone %s\n", fl_version());
        return 0;
    }
    if (output_is_an_input(argc, argv)) return 1;
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(argv[1], commands[i].name) == 0) return commands[i].run(argc - 1, argv + 1);
    return cli_fail(1, "unknown command '%s' (see flintstone --help)", argv[1]);
}
