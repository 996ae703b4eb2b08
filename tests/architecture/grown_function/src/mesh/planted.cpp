// A planted violation for architecture.function_length_catches_a_grown_function: listed at
// 62 lines in architecture.md here, it has grown to 70.

namespace systole::mesh {

namespace {

int listed_and_grown(int x,
           int y) {
  x += y * 0;
  x += y * 1;
  x += y * 2;
  x += y * 3;
  x += y * 4;
  x += y * 5;
  x += y * 6;
  x += y * 7;
  x += y * 8;
  x += y * 9;
  x += y * 10;
  x += y * 11;
  x += y * 12;
  x += y * 13;
  x += y * 14;
  x += y * 15;
  x += y * 16;
  x += y * 17;
  x += y * 18;
  x += y * 19;
  x += y * 20;
  x += y * 21;
  x += y * 22;
  x += y * 23;
  x += y * 24;
  x += y * 25;
  x += y * 26;
  x += y * 27;
  x += y * 28;
  x += y * 29;
  x += y * 30;
  x += y * 31;
  x += y * 32;
  x += y * 33;
  x += y * 34;
  x += y * 35;
  x += y * 36;
  x += y * 37;
  x += y * 38;
  x += y * 39;
  x += y * 40;
  x += y * 41;
  x += y * 42;
  x += y * 43;
  x += y * 44;
  x += y * 45;
  x += y * 46;
  x += y * 47;
  x += y * 48;
  x += y * 49;
  x += y * 50;
  x += y * 51;
  x += y * 52;
  x += y * 53;
  x += y * 54;
  x += y * 55;
  x += y * 56;
  x += y * 57;
  x += y * 58;
  x += y * 59;
  x += y * 60;
  x += y * 61;
  x += y * 62;
  x += y * 63;
  x += y * 64;
  x += y * 65;
  return x;
}

}  // namespace

struct Drifted {
  Drifted(int a) : a_{a}, b_(a) {
    a_ += 0;
    a_ += 1;
    a_ += 2;
    a_ += 3;
    a_ += 4;
    a_ += 5;
    a_ += 6;
    a_ += 7;
    a_ += 8;
    a_ += 9;
    a_ += 10;
    a_ += 11;
    a_ += 12;
    a_ += 13;
    a_ += 14;
    a_ += 15;
    a_ += 16;
    a_ += 17;
    a_ += 18;
    a_ += 19;
    a_ += 20;
    a_ += 21;
    a_ += 22;
    a_ += 23;
    a_ += 24;
    a_ += 25;
    a_ += 26;
    a_ += 27;
    a_ += 28;
    a_ += 29;
    a_ += 30;
    a_ += 31;
    a_ += 32;
    a_ += 33;
    a_ += 34;
    a_ += 35;
    a_ += 36;
    a_ += 37;
    a_ += 38;
    a_ += 39;
    a_ += 40;
    a_ += 41;
    a_ += 42;
    a_ += 43;
    a_ += 44;
    a_ += 45;
    a_ += 46;
    a_ += 47;
    a_ += 48;
    a_ += 49;
    a_ += 50;
    a_ += 51;
    a_ += 52;
    a_ += 53;
    a_ += 54;
    a_ += 55;
    a_ += 56;
    a_ += 57;
    a_ += 58;
    a_ += 59;
  }
  int a_;
  int b_;
};

}  // namespace systole::mesh
