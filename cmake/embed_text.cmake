# cmake -DIN=file -DOUT=file.c -DNAME=symbol -P embed_text.cmake
# Writes OUT defining `const char NAME[]`: the text of IN, byte for byte.
file(READ "${IN}" text)
string(REPLACE "\\" "\\\\" text "${text}")
string(REPLACE "\"" "\\\"" text "${text}")
string(REPLACE "\n" "\\n\"\n\"" text "${text}")
file(WRITE "${OUT}.tmp" "/* Generated from ${IN} by embed_text.cmake: do not edit. */\nconst char ${NAME}[] =\n\"${text}\";\n")
file(RENAME "${OUT}.tmp" "${OUT}")
