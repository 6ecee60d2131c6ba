#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/core.h"
#include "fl_test.h"

static void test_error_format_names_file_and_line(void)
{
    fl_error err;
    fl_status s =
        fl_fail(&err, FL_ERR_INPUT, "points.xyz", 17, "expected %d numbers, got %d", 3, 2);
    CHECK_EQ_INT(s, FL_ERR_INPUT);
    char buf[1200];
    fl_error_format(&err, buf, sizeof buf);
    CHECK(strcmp(buf, "points.xyz:17: expected 3 numbers, got 2") == 0);
    fl_fail_at_offset(&err, FL_ERR_INPUT, "a.ply", 1234, "truncated");
    fl_error_format(&err, buf, sizeof buf);
    CHECK(strcmp(buf, "a.ply: byte 1234: truncated") == 0);
    CHECK_EQ_INT(fl_fail(NULL, FL_ERR_IO, NULL, -1, "x"), FL_ERR_IO);
}

/* Wrapping an inner error in a new one passes err's own message and file as arguments; the
 * inner text must survive (it used to be cleared before it was read: "skin: "). */
static void test_fail_can_wrap_its_own_message(void)
{
    fl_error err;
    fl_fail(&err, FL_ERR_ALGORITHM, "in.off", 7, "centres are coplanar");
    fl_fail(&err, FL_ERR_INPUT, err.file, err.line, "skin: %s", err.message);
    CHECK_EQ_INT(err.status, FL_ERR_INPUT);
    CHECK(strcmp(err.message, "skin: centres are coplanar") == 0);
    CHECK(strcmp(err.file, "in.off") == 0);
    CHECK_EQ_INT((int)err.line, 7);
    fl_fail_at_offset(&err, FL_ERR_INPUT, err.file, 12, "again: %s", err.message);
    CHECK(strcmp(err.message, "again: skin: centres are coplanar") == 0);
    CHECK(strcmp(err.file, "in.off") == 0);
    CHECK_EQ_INT((int)err.offset, 12);
}

static void test_vec_push_of_nothing_on_empty_vec_is_defined(void)
{
    fl_vec v;
    fl_vec_init(&v, sizeof(double));
    CHECK(fl_vec_push(&v, NULL, 0) == 0);
    CHECK(v.count == 0 && v.data == NULL);
    fl_vec_free(&v);
}

static void test_alloc_array_refuses_overflowing_sizes(void)
{
    CHECK(fl_alloc_array(SIZE_MAX / 2, 4) == NULL);
    CHECK(fl_calloc_array(SIZE_MAX / 8, 16) == NULL);
    void *p = fl_alloc_array(10, 8);
    CHECK(p != NULL);
    CHECK(fl_realloc_array(p, SIZE_MAX / 4, 8) == NULL);
    free(p);
}

static void test_vec_grows_and_keeps_contents(void)
{
    fl_vec v;
    fl_vec_init(&v, sizeof(int));
    for (int i = 0; i < 10000; i++)
        CHECK(fl_vec_push(&v, &i, 1) == 0);
    CHECK_EQ_INT(v.count, 10000);
    int ok = 1;
    for (int i = 0; i < 10000; i++)
        ok &= ((int *)v.data)[i] == i;
    CHECK(ok);
    CHECK(fl_vec_push(&v, NULL, 0) == 0 && v.count == 10000);
    int *p = fl_vec_release(&v);
    CHECK(p && p[9999] == 9999);
    CHECK(v.data == NULL && v.count == 0);
    free(p);
}

static void test_out_file_is_atomic(void)
{
    const char *path = "core_atomic_test.txt";
    FILE *f = fopen(path, "w");
    fputs("old", f);
    fclose(f);
    fl_out_file out;
    fl_error err;
    CHECK_STATUS(fl_out_open(&out, path, 0, &err), FL_OK, &err);
    fputs("new content", out.fp);
    /* Before commit the target still holds the old content. */
    char buf[64] = {0};
    f = fopen(path, "r");
    CHECK(fgets(buf, sizeof buf, f) && strcmp(buf, "old") == 0);
    fclose(f);
    fl_out_abort(&out);
    CHECK(access(out.tmp_path, F_OK) != 0);
    f = fopen(path, "r");
    CHECK(fgets(buf, sizeof buf, f) && strcmp(buf, "old") == 0);
    fclose(f);
    CHECK_STATUS(fl_out_open(&out, path, 0, &err), FL_OK, &err);
    fputs("new content", out.fp);
    CHECK_STATUS(fl_out_commit(&out, &err), FL_OK, &err);
    f = fopen(path, "r");
    CHECK(fgets(buf, sizeof buf, f) && strcmp(buf, "new content") == 0);
    fclose(f);
    remove(path);
    CHECK_STATUS(fl_out_open(&out, "/nonexistent-dir/x.off", 0, &err), FL_ERR_IO, &err);
}

static void test_path_extension_is_lowercased(void)
{
    char ext[16];
    fl_path_extension("dir.v2/Model.PLY", ext, sizeof ext);
    CHECK(strcmp(ext, "ply") == 0);
    fl_path_extension("dir.v2/noext", ext, sizeof ext);
    CHECK(strcmp(ext, "") == 0);
    fl_path_extension(".hidden", ext, sizeof ext);
    CHECK(strcmp(ext, "") == 0);
}

FL_TEST_MAIN(FL_TEST_CASE(test_error_format_names_file_and_line),
             FL_TEST_CASE(test_fail_can_wrap_its_own_message),
             FL_TEST_CASE(test_alloc_array_refuses_overflowing_sizes),
             FL_TEST_CASE(test_vec_grows_and_keeps_contents),
             FL_TEST_CASE(test_vec_push_of_nothing_on_empty_vec_is_defined),
             FL_TEST_CASE(test_out_file_is_atomic), FL_TEST_CASE(test_path_extension_is_lowercased))
