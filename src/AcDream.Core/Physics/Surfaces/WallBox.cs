using System.Numerics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>A box seen from above and a height band, landblock-local metres: where a call's sweeps stay.</summary>
internal readonly record struct WallBox(Vector2 Lo, Vector2 Hi, float ZLow, float ZHigh);
