# Netgen's nglib (Debian libnglib-dev): the tet mesher behind mesh::tetrahedralize. FindNglib.cmake locates it.
find_package(Nglib REQUIRED)
