using System.Reflection;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Body;

/// <summary>The engine's private body parts, for tests that call the plan directly.</summary>
internal static class EngineParts
{
    public static BodyPlanner Planner(PhysicsEngine engine) => (BodyPlanner)Field(engine, "_planner");

    public static BodyResolver Body(PhysicsEngine engine) => (BodyResolver)Field(engine, "_body");

    private static object Field(PhysicsEngine engine, string name) =>
        typeof(PhysicsEngine).GetField(name, BindingFlags.NonPublic | BindingFlags.Instance)!.GetValue(engine)!;
}
