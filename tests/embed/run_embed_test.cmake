# Run by CTest: configures, builds and runs the consumer project in EMBED_SOURCE_DIR against
# the scratch install PREFIX (install.cmake; see consumer.cmake for the other variables).
include(${CMAKE_CURRENT_LIST_DIR}/consumer.cmake)

build_consumer(${EMBED_SOURCE_DIR} ${WORK_DIR}/build)
run(${WORK_DIR}/build/embed_demo ${PREFIX}/share/ossa/levels/default.json ${PREFIX}/share/ossa/assets/creatures/examples.json)
# load_level reads Tiled and LDtk files for embedders too (pugixml and zlib come through
# the package config).
run(${WORK_DIR}/build/embed_demo ${EMBED_SOURCE_DIR}/../level/data/tiles_zlib.tmx ${PREFIX}/share/ossa/assets/creatures/examples.json)
run(${WORK_DIR}/build/embed_demo "${EMBED_SOURCE_DIR}/../level/data/world.ldtk#Level_1" ${PREFIX}/share/ossa/assets/creatures/examples.json)
