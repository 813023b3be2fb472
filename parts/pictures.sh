#!/bin/sh
# Makes each part's picture for the palette (160x160 PNG beside its file) from its demo's
# Camera, at a moment of the demo that shows the part at work. Run from the repository root
# after building: parts/pictures.sh [path to gdpn]
set -e
G=${1:-build/ci/apps/gdpn/gdpn}
shot() {  # FILE TIME [more options]
  f=$1; t=$2; shift 2
  "$G" render "parts/$f.gdpn.yaml" --size 160x160 --at "$t" -q -o "parts/$f.png" "$@"
}
shot items/small_box 1
shot items/medium_box 1
shot items/large_box 1
shot conveyors/belt_conveyor 1
shot sources_and_sinks/emitter 0.6
shot sources_and_sinks/remover 0.3
shot sensors/diffuse_sensor 2.6 --sensors
shot sensors/through_beam 2.6 --sensors
shot actuators/pusher 1.2
shot storage/bin 2
shot operator/stack_light 3.5
shot operator/push_button 0.2
shot operator/emergency_stop 0.2
shot operator/selector_switch 0.2
shot operator/beacon 0.6
shot items/metal_base 1
shot items/plastic_lid 1
shot sensors/inductive_sensor 1.2 --sensors
shot sensors/capacitive_sensor 1.2 --sensors
shot sensors/code_reader 1.2 --sensors
shot conveyors/scale_conveyor 1.5
shot actuators/pick_and_place 3
shot items/pallet 1.4
shot conveyors/chute 0.3
shot conveyors/curved_belt 2
shot conveyors/roller_conveyor 1
shot actuators/elevator 3.5
shot storage/stacker 7
shot conveyors/turntable 3.5
shot conveyors/transfer 4.3
shot conveyors/stopper_belt 3
shot actuators/pivot_arm_sorter 1.6
shot operator/potentiometer 0.2
shot operator/digital_display 1.3
shot sensors/light_array 2.5 --sensors
