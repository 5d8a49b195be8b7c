// tests/expect_input_error.hpp — the check every validation test uses.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "skelconv/errors.hpp"

namespace skelconv::test {

/// Runs `construct`, expecting InputError located at `where` whose problem
/// contains `problem`.
template <class Construct>
void expect_input_error(Construct construct, const std::string& where, const std::string& problem) {
  try {
    construct();
    ADD_FAILURE() << "no InputError; expected " << where << ": " << problem;
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), where) << error.what();
    EXPECT_NE(error.problem().find(problem), std::string::npos) << error.what();
  }
}

}  // namespace skelconv::test
