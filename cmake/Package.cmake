# The Debian package: `cpack -G DEB` in a release build folder writes gdpn_VERSION_ARCH.deb
# (tests/package/package_check.sh builds and checks it). Installed under /usr: gdpn on the
# PATH, the Python module where Debian's Python finds it, the parts library and the examples
# under /usr/share/gdpn, the guides under /usr/share/doc/gdpn, a man page, a desktop entry
# with its icon, and the MIME type of *.gdpn.yaml. The libraries gdpn links come from
# dpkg-shlibdeps; what it opens or runs at run time is declared here.

install(DIRECTORY examples/ DESTINATION share/gdpn/examples FILES_MATCHING PATTERN "*.yaml" PATTERN "*.py"
        PATTERN "*.js" PATTERN "*.md" PATTERN "*.png")
install(FILES packaging/gdpn.desktop DESTINATION share/applications)
install(FILES packaging/gdpn.svg DESTINATION share/icons/hicolor/scalable/apps)
install(FILES packaging/gdpn.xml DESTINATION share/mime/packages)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gdpn)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_CONTACT "gdpn developers <gdpn@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "geometry-driven Petri nets: control logic run against a virtual plant")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Write the control logic of a mechatronic system (conveyors, painting cells, robot arms,\nvehicles) as a hierarchical, timed, coloured Petri net with Python scripts, and run it\nagainst a virtual 3D plant with rigid-body physics and sensors: in an IDE, headless and\nreproducibly, filmed, analysed (state space, CTL and LTL queries, invariants, cycle\ntimes) and served to PLCs over Modbus TCP and OPC UA.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# beside what dpkg-shlibdeps finds: the Python the module is built for (its stdlib runs gdpn's
# scripts), GDAL (opened when a terrain is first read), NumPy (scripts' arrays, camera images)
math(EXPR gdpn_python_next "${Python_VERSION_MINOR} + 1")
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), python3 (<< ${Python_VERSION_MAJOR}.${gdpn_python_next}), python3-numpy, libgdal32")
# gdpn record runs ffmpeg; the HTML report and sweeps use pandas, matplotlib and Dask
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg, python3-pandas, python3-matplotlib, python3-distributed")
include(CPack)
