cmake_minimum_required(VERSION 3.25)
# cmake -DTABLE=file -DTECHNIQUE=name -DOUT=header -P read_table.cmake: reads a
# quality table as the build does and writes technique's generated header text
# to OUT (tests/quality/test_quality_table.sh).
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/gtlab_quality.cmake)
gtlab_quality_table_read(${TABLE})
get_property(rows GLOBAL PROPERTY GTLAB_QUALITY_ROWS_${TECHNIQUE})
gtlab_quality_header_text(${TECHNIQUE} "${rows}" text)
file(WRITE ${OUT} "${text}")
