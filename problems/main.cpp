// beamrotor command line (placeholder until the deck-driven command line lands).
#include <iostream>

int main(int argc, char** argv) {
  std::cout << "beamrotor " << BEAMROTOR_VERSION << "\n";
  return 0;
}
