/* The 3D parts of `flintstone reconstruct`: unlocking (§5.4) and kept triangles (§5.7) as a user
 * sees them — JSON fields, exit codes, and the written mesh re-read by `check` (closed, oriented,
 * genus 0, no self-intersection found by the exact search). */
#include <stdio.h>
#include <string.h>

#include "../cli/cli_run.h"
#include "fl_test.h"

static cli_result r;

/* The 512 flattened-ball volume samples of test_constrict3_locked.c (seed 11): plain
 * constriction locks with a point inside. */
static void write_flat_ball(const char *path)
{
    FILE *f = fopen(path, "w");
    unsigned long long seed = 11;
    for (int i = 0; i < 512; i++) {
        double x, y, z;
        do {
            x = 2 * fl_test_rand01(&seed) - 1;
            y = 2 * fl_test_rand01(&seed) - 1;
            z = 2 * fl_test_rand01(&seed) - 1;
        } while (x * x + y * y + z * z > 1);
        fprintf(f, "%.17g %.17g %.17g\n", x, y, 0.2 * z);
    }
    fclose(f);
}

static void test_cli3_locked_input_is_unlocked_by_flips(void)
{
    write_flat_ball("rec3_ball.xyz");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_ball.xyz --no-augment --json"), 3);
    CHECK(strstr(r.out, "\"all_on_boundary\":false") != NULL);
    CHECK(strstr(r.out, "augmentation is off") != NULL);
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_ball.xyz --json -o rec3_ball.off"), 0);
    CHECK(strstr(r.out, "\"all_on_boundary\":true") != NULL);
    CHECK(strstr(r.out, "\"boundary_vertices\":512") != NULL);
    CHECK(strstr(r.out, "\"flips\":0") == NULL);
    CHECK(strstr(r.out, "\"augmented_c0\":null") == NULL);
    CHECK_EQ_INT(cli_run(&r, "check rec3_ball.off --json"), 0);
    CHECK(strstr(r.out, "\"closed\":true") != NULL);
    CHECK(strstr(r.out, "\"oriented\":true") != NULL);
    CHECK(strstr(r.out, "\"genus\":0") != NULL);
    CHECK(strstr(r.out, "\"self_intersections\":0") != NULL);
    remove("rec3_ball.xyz");
    remove("rec3_ball.off");
}

/* Octahedron plus its centre: the Delaunay faces are the 8 hull triangles and the 12 triangles
 * through the centre. */
static void test_cli3_keep_file(void)
{
    cli_write_file("rec3_oct.xyz", "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n0.01 0.02 0.03\n");
    cli_write_file("rec3_keep.txt", "0 2 4\n1 3 5\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_oct.xyz --keep rec3_keep.txt --json"), 0);
    CHECK(strstr(r.out, "\"keep_missing\":0") != NULL);
    CHECK(strstr(r.out, "\"all_on_boundary\":true") != NULL);
    cli_write_file("rec3_keep.txt", "0 1 2\n"); /* uses the diagonal 0-1: not a Delaunay face */
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_oct.xyz --keep rec3_keep.txt"), 2);
    CHECK(strstr(r.err, "not a face of the Delaunay") != NULL);
    cli_write_file("rec3_keep.txt", "0 2\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_oct.xyz --keep rec3_keep.txt"), 2);
    CHECK(strstr(r.err, "3 indices") != NULL);
    cli_write_file("rec3_keep.txt", "0 2 9\n");
    CHECK_EQ_INT(cli_run(&r, "reconstruct rec3_oct.xyz --keep rec3_keep.txt"), 2);
    CHECK(strstr(r.err, "out of range") != NULL);
    remove("rec3_oct.xyz");
    remove("rec3_keep.txt");
}

FL_TEST_MAIN(FL_TEST_CASE(test_cli3_locked_input_is_unlocked_by_flips),
             FL_TEST_CASE(test_cli3_keep_file))
