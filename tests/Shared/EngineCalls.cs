using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Testing;

/// <summary>
/// The argument lists many tests were written with, each made one request of the engine's general calls:
/// <see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/> and <see cref="PhysicsEngine.Cast(in CastRequest)"/>.
/// A cast's end point becomes its delta (<c>to − from</c>).
/// </summary>
internal static class EngineCalls
{
    /// <summary>A move with its report.</summary>
    public static ResolveResult Resolve(
        this PhysicsEngine engine, Vector3 position, uint cellId, Vector3 delta, float stepUp, in MovementOptions options, out MoveReport report)
    {
        MoveResult result = engine.Resolve(new MoveRequest(position, cellId, delta, stepUp) { Options = options, WithReport = true });
        report = result.Report;
        return result.Answer;
    }

    /// <summary>A registered mover's move.</summary>
    public static ResolveResult Resolve(
        this PhysicsEngine engine, Vector3 position, uint cellId, Vector3 delta, float stepUp, in MovementOptions options, uint moverId) =>
        engine.Resolve(new MoveRequest(position, cellId, delta, stepUp) { Options = options, MoverId = moverId }).Answer;

    /// <summary>A registered mover's move with its report and the movers it touched.</summary>
    public static ResolveResult Resolve(
        this PhysicsEngine engine, Vector3 position, uint cellId, Vector3 delta, float stepUp, in MovementOptions options, uint moverId,
        Span<uint> touched, out int touchedCount, out MoveReport report)
    {
        MoveResult result = engine.Resolve(new MoveRequest(position, cellId, delta, stepUp) { Options = options, MoverId = moverId, WithReport = true }, touched);
        touchedCount = result.TouchedCount;
        report = result.Report;
        return result.Answer;
    }

    /// <summary>A cast from <paramref name="from"/> to <paramref name="to"/>, ignoring the mover <paramref name="moverId"/>.</summary>
    public static CastHit Cast(this PhysicsEngine engine, Vector3 from, uint fromCellId, Vector3 to, in CastOptions options, uint moverId = 0) =>
        engine.Cast(new CastRequest(from, fromCellId, to - from) { Options = options, MoverId = moverId });
}
