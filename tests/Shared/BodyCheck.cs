using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced): one body call against the reference.

/// <summary>One body call checked against <see cref="ReferenceBody"/>, started from the engine's own start.</summary>
internal readonly record struct BodyCall(
    ResolveResult Engine,
    ReferenceBody.Result Reference,
    double Distance,
    double Overlap,
    bool Tunnelled,
    bool WellConditioned,
    double Tolerance,
    string What)
{
    /// <summary>Whether the end position agrees with the reference within <see cref="Tolerance"/> (ill-conditioned calls pass).</summary>
    public bool Agrees => !WellConditioned || Distance <= Tolerance;

    public override string ToString() => FormattableString.Invariant(
        $"{What} → engine {Engine}; reference end {Reference.End} (contacts {Reference.Contacts}, stopped {Reference.Stopped}); |engine − reference| {Distance:E3} m (tolerance {Tolerance:E3}, well-conditioned {WellConditioned}); overlap {Overlap:E3} m; tunnelled {Tunnelled}");
}

/// <summary>
/// Compares the engine with <see cref="ReferenceBody"/>. The reference gets the clearance the engine
/// documents for the body: its radius plus <see cref="PhysicsConstants.BodySkin"/> plus twice the float
/// spacing of the largest coordinate the move reaches (world or landblock-local), so the float rounding
/// of the answer never puts the body into a wall. Overlap is measured against the radius alone.
/// </summary>
internal static class BodyCheck
{
    /// <summary>End positions agree within this (metres), plus the world frame's rounding (see <see cref="Tolerance"/>).</summary>
    public const double EndTolerance = 0.001;

    /// <summary>The most a body may overlap a wall after a call, metres.</summary>
    public const double OverlapLimit = 0.001;

    /// <summary>
    /// A call is well-conditioned when the reference's end moves by less than <see cref="EndTolerance"/>/2
    /// plus 1.5 times the change when its clearance is grown or shrunk by this (metres), or by two
    /// float spacings of the world frame where that is more: a grazing touch of a wall's end decides the slide's direction by the square
    /// root of the depth, and whether a wedge stops the body or lets it slide can turn on a hair, so such
    /// near-misses are not compared (the body may sit that far inside its skin; the reference has none).
    /// </summary>
    public const double Conditioning = 1e-4;

    /// <summary>
    /// ... and when turning its move by this (radians) either way moves its end by less than
    /// <see cref="EndTolerance"/>/2 plus twice what the turn itself does: a slide that leaves a wedge
    /// nearly square to the move is stopped or not by a hair of the contact normal.
    /// </summary>
    public const double Turn = 1e-3;

    public static BodyCall Compare(BodyCourse course, Vector3 pos, uint cell, Vector3 delta, float step, in MovementOptions options)
    {
        MoverBody body = options.Body!.Value;
        ResolveResult r = course.Engine.Resolve(pos, cell, delta, step, options);
        double zLow = pos.Z + step, zHigh = pos.Z + body.Height;
        ReferenceBody.Vec2 start = course.Local(pos), move = new(delta.X, delta.Y);
        double clearance = body.Radius + Skin(course, pos, delta, body.Radius);
        ReferenceBody.Result reference = course.Reference.Move(start, move, zLow, zHigh, clearance);
        ReferenceBody.Vec2 end = course.Local(r.Position);
        double distance = (end - reference.End).Length;
        double overlap = body.Radius - course.Reference.Clearance(end, zLow, zHigh);
        bool tunnelled = course.Reference.Crosses(reference.End, end, zLow, zHigh);
        bool conditioned = !reference.Stuck;
        if (conditioned && distance > EndTolerance / 4)
        {
            double by = Math.Max(Conditioning, 2 * Spacing(pos, delta));
            ReferenceBody.Result thinner = course.Reference.Move(start, move, zLow, zHigh, clearance - by);
            ReferenceBody.Result fatter = course.Reference.Move(start, move, zLow, zHigh, clearance + by);
            double moves = (EndTolerance / 2) + (1.5 * by); // a contact moves the end by the change itself, a right corner by √2 times it
            conditioned = (thinner.End - reference.End).Length < moves && (fatter.End - reference.End).Length < moves;
            foreach (double turn in new[] { -Turn, Turn })
            {
                var turned = new ReferenceBody.Vec2((move.X * Math.Cos(turn)) - (move.Y * Math.Sin(turn)), (move.X * Math.Sin(turn)) + (move.Y * Math.Cos(turn)));
                ReferenceBody.Result aside = course.Reference.Move(start, turned, zLow, zHigh, clearance);
                conditioned &= (aside.End - reference.End).Length < (EndTolerance / 2) + (2 * Turn * move.Length);
            }
        }

        string what = FormattableString.Invariant($"{course.Name}: body r {body.Radius} h {body.Height} at {pos:R} in 0x{cell:X8} (local {start}) moving {delta:R}, step {step}");
        return new BodyCall(r, reference, distance, overlap, tunnelled, conditioned, Tolerance(course, pos, delta), what);
    }

    /// <summary>
    /// <see cref="EndTolerance"/> plus four float spacings of the world coordinates: the world frame
    /// rounds each corner of the body's path once (near the far corner of the world in the global frame
    /// a spacing is 3.9 mm, so no float answer can be within 1 mm there).
    /// </summary>
    public static double Tolerance(BodyCourse course, Vector3 pos, Vector3 delta) => EndTolerance + (4.0 * Spacing(pos, delta));

    /// <summary>The float spacing of the world coordinates a move from <paramref name="pos"/> by <paramref name="delta"/> reaches.</summary>
    public static double Spacing(Vector3 pos, Vector3 delta)
    {
        float largest = MathF.Max(MathF.Abs(pos.X), MathF.Abs(pos.Y)) + delta.Length() + 1f;
        return MathF.BitIncrement(largest) - largest;
    }

    /// <summary>The body's documented skin beyond its radius for a move from <paramref name="pos"/>: <see cref="PhysicsConstants.BodySkin"/> + 2 float spacings.</summary>
    public static double Skin(BodyCourse course, Vector3 pos, Vector3 delta, float radius)
    {
        ReferenceBody.Vec2 local = course.Local(pos);
        float largest = (float)Math.Max(Math.Max(Math.Abs(pos.X), Math.Abs(pos.Y)), Math.Max(Math.Abs(local.X), Math.Abs(local.Y))) + delta.Length() + radius;
        return PhysicsConstants.BodySkin + (2.0 * (MathF.BitIncrement(largest) - largest));
    }
}
