// feel: render, check, inspect and play force-feedback sensations from the command line.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"

int main(int argc, char** argv) {
    try {
        const std::vector<std::string> args(argv, argv + argc);
        return feel::cli::run_main(args, std::cout, std::cerr);
    } catch (const std::exception& e) {  // run() catches everything; this is the last guard
        std::cerr << "feel: internal error: " << e.what() << '\n';
    } catch (...) {
        std::cerr << "feel: internal error\n";
    }
    return feel::cli::kExitFailure;
}
