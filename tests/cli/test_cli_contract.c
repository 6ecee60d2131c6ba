#include "cli_run.h"
#include "fl_test.h"

static cli_result r;

static void test_help_and_version_exit_zero(void)
{
    CHECK_EQ_INT(cli_run(&r, "--help"), 0);
    CHECK(strstr(r.out, "usage: flintstone") != NULL);
    CHECK_EQ_INT(cli_run(&r, "--version"), 0);
    CHECK(strncmp(r.out, "flintstone ", 11) == 0);
    CHECK(strstr(r.out, fl_version()) != NULL);
}

static void test_no_arguments_is_a_usage_error(void)
{
    CHECK_EQ_INT(cli_run(&r, ""), 1);
    CHECK(strstr(r.err, "usage:") != NULL);
}

static void test_unknown_command_is_a_usage_error_on_stderr(void)
{
    CHECK_EQ_INT(cli_run(&r, "frobnicate"), 1);
    CHECK(strncmp(r.err, "flintstone: error: ", 19) == 0);
    CHECK(strstr(r.err, "frobnicate") != NULL);
    CHECK(r.out[0] == '\0');
}

FL_TEST_MAIN(FL_TEST_CASE(test_help_and_version_exit_zero),
             FL_TEST_CASE(test_no_arguments_is_a_usage_error),
             FL_TEST_CASE(test_unknown_command_is_a_usage_error_on_stderr))
