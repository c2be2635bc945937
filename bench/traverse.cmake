# bench_traverse: Rays' TriangleBvh against Embree 3 on the same ray sets (bench/traverse.cpp).
# Included from bench/CMakeLists.txt when the project is configured with -DRAYS_BUILD_BENCH=ON;
# needs libembree-dev (Embree 3) and the rays_core library target.
#   cmake -S . -B build-bench -DRAYS_BUILD_BENCH=ON && cmake --build build-bench --target bench_traverse
#   ./build-bench/bench/bench_traverse            (about a minute; --quick for a smoke run)
find_package(embree 3 REQUIRED)
find_package(Threads REQUIRED)

add_executable(bench_traverse ${CMAKE_CURRENT_LIST_DIR}/traverse.cpp)
target_compile_options(bench_traverse PRIVATE ${RAYS_WARNINGS})
target_include_directories(bench_traverse PRIVATE ${CMAKE_CURRENT_LIST_DIR}/../tests)  # support/icosphere.h
target_link_libraries(bench_traverse PRIVATE rays_core embree Threads::Threads ZLIB::ZLIB)  # tinyobjloader: compiled into rays_core
# The models and scenes it reads ship with the project (scenes/models/, bench/scenes/course/).
target_compile_definitions(bench_traverse PRIVATE RAYS_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
