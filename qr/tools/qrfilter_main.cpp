// qrfilter --order N --fc HZ --fs HZ [--frac BITS] [--at HZ,HZ,...]: see filter_tool.cpp.
#include <iostream>

#include "filter_tool.hpp"

int main(int argc, char** argv) { return qr::tools::run_qrfilter(argc, argv, std::cout, std::cerr); }
