// A header saved on Windows: CRLF line ends and no newline after its last line.
float Twice(float x) { return 2.0 * x; }