#include <iostream>

int main() {
    std::cerr << "glint: the CLI is under construction\n";
    return 1;
}
