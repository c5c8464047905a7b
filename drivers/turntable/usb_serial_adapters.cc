#include "drivers/turntable/usb_serial_adapters.h"

namespace avc::turntable {

const std::vector<usb::KnownUsbDevice>& DefaultKnownAdapters() {
  static const std::vector<usb::KnownUsbDevice> adapters = {
      {0x0403, 0x6001, "FTDI FT232R"},         {0x0403, 0x6010, "FTDI FT2232"},
      {0x0403, 0x6011, "FTDI FT4232"},         {0x0403, 0x6015, "FTDI FT231X"},
      {0x067b, 0x2303, "Prolific PL2303"},     {0x1a86, 0x7523, "WCH CH340"},
      {0x10c4, 0xea60, "Silicon Labs CP210x"},
  };
  return adapters;
}

}  // namespace avc::turntable
