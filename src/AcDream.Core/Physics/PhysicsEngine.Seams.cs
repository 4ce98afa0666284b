using System.Numerics;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Body;

namespace AcDream.Core.Physics;

// The tests' seams: a body's move asked in parts, as Resolve asks them (the movers are not read here).
public sealed partial class PhysicsEngine
{
    /// <summary>Tests' seam: whether a body's move needs no plan (<see cref="BodyPlanner.IsOpenGround"/>), as <c>Resolve</c> asks it.</summary>
    internal bool IsOpenGround(Vector3 position, uint cellId, Vector2 move, MoverBody body)
    {
        var lands = new Neighbourhood(_registry); // (the movers are not read here)
        MovementOptions options = new() { Body = body };
        var query = new MoveQuery(ref lands, position, cellId, move, 0f, in options);
        return _planner.IsOpenGround(ref query, move, body);
    }

    /// <summary>Tests' seam: a body's move always planned (<see cref="BodyResolver.Resolve"/>), never the open-ground shortcut.</summary>
    internal ResolveResult ResolvePlanned(Vector3 position, uint cellId, Vector2 move, float stepUpHeight, in MovementOptions options)
    {
        var lands = new Neighbourhood(_registry); // (the movers are not read here)
        var query = new MoveQuery(ref lands, position, cellId, move, stepUpHeight, in options);
        return _motion.Planned(ref query);
    }

    /// <summary>Tests' seam: how far a body overlaps the walls of its band beyond its sink (<see cref="BodyPlanner.Overlap"/>), metres.</summary>
    internal float BodyOverlap(Vector3 position, uint cellId, float stepUpHeight, MoverBody body)
    {
        var lands = new Neighbourhood(_registry); // (the movers are not read here)
        MovementOptions options = new() { Body = body };
        var query = new MoveQuery(ref lands, position, cellId, Vector2.Zero, stepUpHeight, in options);
        return _planner.Overlap(ref query, position, cellId, body, out _);
    }
}
