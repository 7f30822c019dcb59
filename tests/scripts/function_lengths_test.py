#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Tests of scripts/function_lengths.py on small C++ snippets written to a temporary folder.

Each snippet holds bodies just over and just under a limit of 5 lines, next to the constructs
that could mislead a lexical reader: braces inside comments and literals, classes and
namespaces, initializer lists and lambdas.
"""

import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "function_lengths.py")
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(SCRIPT))
import function_lengths  # noqa: E402


def bodies(source):
    """(name, lines) of every function body of the snippet, sorted."""
    text = textwrap.dedent(source)
    return sorted((name, text.count("\n", open_at, close_at) + 1)
                  for name, _, open_at, close_at in function_lengths.function_bodies(text))


class Bodies(unittest.TestCase):
    def test_counts_from_the_opening_to_the_closing_brace_both_included(self):
        self.assertEqual(bodies("""
            int one() { return 1; }
            int three() {
              return 3;
            }
            """), [("one", 1), ("three", 3)])

    def test_braces_in_comments_and_literals_are_not_read(self):
        found = bodies(r'''
            // void commented() {
            /* } { */
            const char* f() {
              const char* a = "}{\"}";
              const char* b = R"x(
                } } )" {
              )x";
              char c = '}';
              char d = '\'';
              int e = 1'000 + '}';
              return a;
            }
            #define OPEN {
            int g() { return 0; }
            ''')
        self.assertEqual(found, [("f", 10), ("g", 1)])

    def test_namespaces_and_classes_are_not_functions_but_their_methods_are(self):
        found = bodies("""
            namespace outer {
            namespace {
            struct Point {
              int x{0};
              int y = {1};
              int sum() const {
                return x + y;
              }
              bool operator==(const Point& other) const { return x == other.x; }
              bool operator()(int a) const { return a > 0; }
              operator bool() const { return x != 0; }
            };
            enum class Colour { kRed, kGreen };
            extern "C" {
            int c_function(void) { return 0; }
            }
            }  // namespace
            template <typename T>
            class Box final : public Base<T> {
             public:
              explicit Box(T value) : value_{value}, other_(value), more_{{1, 2}} {
                check();
              }
              ~Box() override {}
             private:
              T value_;
            };
            }  // namespace outer
            void outer::Free::method() noexcept {
            }
            auto trailing(int a) -> std::vector<int> {
              return {a};
            }
            """)
        self.assertEqual(found, sorted([
            ("Point::sum", 3), ("Point::operator==", 1), ("Point::operator()", 1),
            ("Point::operator bool", 1), ("c_function", 1), ("Box::Box", 3), ("Box::~Box", 1),
            ("outer::Free::method", 2), ("trailing", 3)]))

    def test_lambdas_and_inner_braces_belong_to_their_function(self):
        found = bodies("""
            void with_lambda() {
              const auto f = [&](int a) -> int {
                struct Local { int g() { return 1; } };
                return a;
              };
              std::vector<std::vector<int>> v = {{1, 2}, {3}};
              if (f(1)) {
                enum Inner { kA, kB };
              }
            }
            """)
        self.assertEqual(found, [("with_lambda", 10)])

    def test_lambdas_outside_functions_are_their_own_functions(self):
        found = bodies("""
            const auto kTable = [] {
              return 1;
            }();
            const std::vector<Case> kCases = {{"a", [](int x) { return x; }}};
            std::function<int(int)> g = [](int a) -> int {
              return a;
            };
            int after() { return 0; }
            """)
        self.assertEqual(found, [("<lambda>", 1), ("<lambda>", 3), ("<lambda>", 3), ("after", 1)])

    def test_googletest_bodies_are_named_after_their_suite_and_test(self):
        found = bodies("""
            TEST(Suite, Name) {
              EXPECT_TRUE(true);
            }
            TEST_F(Fixture, Other) { EXPECT_TRUE(true); }
            """)
        self.assertEqual(found, [("TEST(Suite, Name)", 3), ("TEST_F(Fixture, Other)", 1)])

    def test_unbalanced_braces_are_an_error(self):
        with self.assertRaises(ValueError):
            bodies("void f() {\n")
        with self.assertRaises(ValueError):
            bodies("void f() {}\n}\n")


class CommandLine(unittest.TestCase):
    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def test_prints_the_long_bodies_and_fails_then_passes_with_their_file_excluded(self):
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "model"))
            os.makedirs(os.path.join(root, "tests", "build-x"))
            long_body = "int long_one() {\n" + "  ++x;\n" * 5 + "}\n"
            short_body = "int short_one() {\n" + "  ++x;\n" * 4 + "}\n"
            with open(os.path.join(root, "model", "a.cpp"), "w") as f:
                f.write("int x;\n" + long_body + short_body)
            with open(os.path.join(root, "model", "b.h"), "w") as f:
                f.write("// generated by: a tool; do not edit\n" + long_body)
            with open(os.path.join(root, "tests", "build-x", "c.cpp"), "w") as f:
                f.write(long_body)
            result = self.run_script("--root", root, "--max-lines", "6")
            self.assertEqual(result.returncode, 1, result.stderr)
            self.assertEqual(result.stdout, "model/a.cpp:2: long_one: 7 lines\n")
            result = self.run_script("--root", root, "--max-lines", "7")
            self.assertEqual((result.returncode, result.stdout), (0, ""))
            result = self.run_script("--root", root, "--max-lines", "6",
                                     "--exclude", "model/a.cpp")
            self.assertEqual((result.returncode, result.stdout), (0, ""))

    def test_a_file_whose_braces_do_not_balance_is_an_error(self):
        with tempfile.TemporaryDirectory() as root:
            path = os.path.join(root, "broken.cpp")
            with open(path, "w") as f:
                f.write("void f() {\n")
            result = self.run_script(path)
            self.assertEqual(result.returncode, 2)
            self.assertIn("broken.cpp", result.stderr)


if __name__ == "__main__":
    unittest.main()
