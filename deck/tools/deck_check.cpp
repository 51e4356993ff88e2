// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-deck-check NAME_0000.rad: the deck check of `hbm-solver --check` on its own.
// Exit 0 valid, 1 deck errors, 2 bad command-line use.
#include "hbm/deck/check_command.hpp"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]).empty() || argv[1][0] == '-') {
    std::cerr << "usage: hbm-deck-check NAME_0000.rad\n";
    return 2;
  }
  return hbm::deck::run_check(argv[1], std::cout, std::cerr);
}
