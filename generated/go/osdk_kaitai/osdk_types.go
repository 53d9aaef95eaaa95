// Generated from spec/*.ksy by tools/regen.py (tools/tables.py). Do not edit.

package osdk_kaitai

import "reflect"

// Types holds every struct type of this package, one per ksy type of the
// tables' model (generated/tables/osdk_tables.json).
var Types = []reflect.Type{
	reflect.TypeOf(OsdkBroadcastA3Fw31{}),
	reflect.TypeOf(OsdkBroadcastItems{}),
	reflect.TypeOf(OsdkBroadcastItems_ControlInfo{}),
	reflect.TypeOf(OsdkBroadcastItems_Gimbal{}),
	reflect.TypeOf(OsdkBroadcastItems_GimbalLimit{}),
	reflect.TypeOf(OsdkBroadcastItems_GpsDetail{}),
	reflect.TypeOf(OsdkBroadcastItems_Magnetometer{}),
	reflect.TypeOf(OsdkBroadcastItems_Position{}),
	reflect.TypeOf(OsdkBroadcastItems_Quaternion{}),
	reflect.TypeOf(OsdkBroadcastItems_Rc{}),
	reflect.TypeOf(OsdkBroadcastItems_RtkDetail{}),
	reflect.TypeOf(OsdkBroadcastItems_TimeStamp{}),
	reflect.TypeOf(OsdkBroadcastItems_Vector3f{}),
	reflect.TypeOf(OsdkBroadcastItems_Velocity{}),
	reflect.TypeOf(OsdkBroadcastM100Fw23{}),
	reflect.TypeOf(OsdkBroadcastM100Fw31{}),
	reflect.TypeOf(OsdkControlMode{}),
	reflect.TypeOf(OsdkFrame{}),
	reflect.TypeOf(OsdkFrame_FrameData{}),
	reflect.TypeOf(OsdkMovementControl{}),
	reflect.TypeOf(OsdkPayload{}),
	reflect.TypeOf(OsdkPayload_ActivationAckValue{}),
	reflect.TypeOf(OsdkPayload_ActivationRequest{}),
	reflect.TypeOf(OsdkPayload_Broadcast{}),
	reflect.TypeOf(OsdkPayload_ControlAckValue{}),
	reflect.TypeOf(OsdkPayload_ControlRequest{}),
	reflect.TypeOf(OsdkPayload_FrequencyAckValue{}),
	reflect.TypeOf(OsdkPayload_FrequencyRequest{}),
	reflect.TypeOf(OsdkPayload_LostControl{}),
	reflect.TypeOf(OsdkPayload_LostControlAckValue{}),
	reflect.TypeOf(OsdkPayload_UnknownValue{}),
	reflect.TypeOf(OsdkPayload_VersionAckValue{}),
	reflect.TypeOf(OsdkPayload_VersionQuery{}),
}
