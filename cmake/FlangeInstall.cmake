# SPDX-License-Identifier: MIT
# `cmake --install build --prefix P` and `cpack -G DEB` (README, "Install"): P/bin/flange and its
# data folder P/share/flange (runtime/data_dir.h), laid out as in the repository so that the
# executable finds everything relative to itself:
#   rtl/       the RTL, lint waivers, Yosys script, Basys-3 top, constraints and Vivado script
#   coeffs/    the checked-in coefficient sets (the thesis's filters, coeffs/regenerate.sh)
#   tb/ model/ the sources and headers of the Verilated runner that `flange cosim` and
#              `flange run --engine rtl` build per coefficient set at run time
#   lib/       the two archives that runner links (libflange_tb.a, libflange_model.a)
include(GNUInstallDirs)
set(FLANGE_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/flange)

install(TARGETS flange RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/rtl DESTINATION ${FLANGE_DATA_DESTINATION}
        USE_SOURCE_PERMISSIONS)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/coeffs/ DESTINATION ${FLANGE_DATA_DESTINATION}/coeffs
        PATTERN src EXCLUDE PATTERN CMakeLists.txt EXCLUDE PATTERN regenerate.sh EXCLUDE)
# The runner's main and DUT wrapper and every header they include (tb/cosim_main.cpp).
install(FILES ${PROJECT_SOURCE_DIR}/tb/cosim_main.cpp ${PROJECT_SOURCE_DIR}/tb/iir_core_dut.cpp
              ${PROJECT_SOURCE_DIR}/tb/cosim_run.h ${PROJECT_SOURCE_DIR}/tb/iir_core_dut.h
              ${PROJECT_SOURCE_DIR}/tb/stream_run.h ${PROJECT_SOURCE_DIR}/tb/verilated_dut.h
              ${PROJECT_SOURCE_DIR}/tb/rtl_coverage.h ${PROJECT_SOURCE_DIR}/tb/stimulus.h
        DESTINATION ${FLANGE_DATA_DESTINATION}/tb)
install(FILES ${PROJECT_SOURCE_DIR}/model/filter_json.h DESTINATION ${FLANGE_DATA_DESTINATION}/model)
install(TARGETS flange_tb flange_model ARCHIVE DESTINATION ${FLANGE_DATA_DESTINATION}/lib)

# The Debian package. Depends: the shared libraries flange links (dpkg-shlibdeps), and what it
# runs: Verilator, g++, make, zlib (FST tracing) and the fmt and CLI11 headers for the runner it
# builds per coefficient set; Yosys for `flange synth`; gnuplot for `flange design`'s plot.
set(FLANGE_PACKAGE_MAINTAINER
    "flange maintainers <maintainers@users.noreply.h-seed-48ee596c.example>"
    CACHE STRING "Maintainer field of the Debian package")
set(CPACK_PACKAGE_NAME flange)
set(CPACK_PACKAGE_VENDOR flange)
set(CPACK_PACKAGE_CONTACT "${FLANGE_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "FPGA IIR filter for wheel-flange wear measurement: design, co-simulation, synthesis, host")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(flange_runs "verilator (>= 5)" g++ make zlib1g-dev libfmt-dev libcli11-dev yosys
                "gnuplot-nox | gnuplot")
list(JOIN flange_runs ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
set(CPACK_GENERATOR DEB)
include(CPack)
